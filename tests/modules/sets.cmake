# The parameter sets of the per-module tests: modtb_set(<bench> <test name> TOP ... SOURCES ...
# PARAMS ...), see CMakeLists.txt. Test names are ctest's modules_<name>.
modtb_set(min_tree min_tree_n8_l3 TOP fpstereo_min_tree SOURCES fpstereo_min_tree.v fpstereo_reduction_tree.v fpstereo_unique_join.v
          PARAMS N=8 W=8 IDX_W=3 LEVELS_PER_STAGE=3 LAT=1)
modtb_set(min_tree min_tree_n13_l1 TOP fpstereo_min_tree SOURCES fpstereo_min_tree.v fpstereo_reduction_tree.v fpstereo_unique_join.v
          PARAMS N=13 W=5 IDX_W=4 LEVELS_PER_STAGE=1 LAT=4)
modtb_set(min_tree min_tree_n6_l2 TOP fpstereo_min_tree SOURCES fpstereo_min_tree.v fpstereo_reduction_tree.v fpstereo_unique_join.v
          PARAMS N=6 W=3 IDX_W=3 LEVELS_PER_STAGE=2 LAT=2)
modtb_set(unique_tree unique_tree_n8_l3 TOP fpstereo_unique_tree
          SOURCES fpstereo_unique_tree.v fpstereo_reduction_tree.v fpstereo_unique_join.v PARAMS N=8 W=10 IDX_W=3 LEVELS_PER_STAGE=3 LAT=1)
modtb_set(unique_tree unique_tree_n13_l2 TOP fpstereo_unique_tree
          SOURCES fpstereo_unique_tree.v fpstereo_reduction_tree.v fpstereo_unique_join.v PARAMS N=13 W=4 IDX_W=4 LEVELS_PER_STAGE=2 LAT=2)
modtb_set(unique_tree unique_tree_n3_l1 TOP fpstereo_unique_tree
          SOURCES fpstereo_unique_tree.v fpstereo_reduction_tree.v fpstereo_unique_join.v PARAMS N=3 W=3 IDX_W=2 LEVELS_PER_STAGE=1 LAT=2)
modtb_set(unique_join unique_join_w6 TOP fpstereo_unique_join SOURCES fpstereo_unique_join.v
          PARAMS W=6 IDX_W=4)
modtb_set(unique_join unique_join_w3 TOP fpstereo_unique_join SOURCES fpstereo_unique_join.v
          PARAMS W=3 IDX_W=3)
modtb_set(median_select median_select_m3_w5 TOP fpstereo_median_select SOURCES fpstereo_median_select.v
          PARAMS M=3 WORD_W=5)
modtb_set(median_select median_select_m5_w8 TOP fpstereo_median_select SOURCES fpstereo_median_select.v
          PARAMS M=5 WORD_W=8)
modtb_set(median_select median_select_m7_w4 TOP fpstereo_median_select SOURCES fpstereo_median_select.v
          PARAMS M=7 WORD_W=4)
modtb_set(axis_skid axis_skid_w8 TOP fpstereo_axis_skid SOURCES fpstereo_axis_skid.v PARAMS DATA_W=8)
modtb_set(axis_skid axis_skid_w37 TOP fpstereo_axis_skid SOURCES fpstereo_axis_skid.v PARAMS DATA_W=37)
modtb_set(window window_n3_s5 TOP fpstereo_window SOURCES fpstereo_window.v fpstereo_ram_sdp.v
          PARAMS N=3 WORD_W=8 ROW_SLOTS=5 ADDR_W=3)
modtb_set(window window_n7_s16 TOP fpstereo_window SOURCES fpstereo_window.v fpstereo_ram_sdp.v
          PARAMS N=7 WORD_W=4 ROW_SLOTS=16 ADDR_W=5)
modtb_set(window window_n5_s3 TOP fpstereo_window SOURCES fpstereo_window.v fpstereo_ram_sdp.v
          PARAMS N=5 WORD_W=10 ROW_SLOTS=3 ADDR_W=2)
modtb_set(window window_n7_p2_c9_s10 TOP fpstereo_window SOURCES fpstereo_window.v fpstereo_ram_sdp.v
          PARAMS N=7 WORD_W=8 P=2 COLS=9 ROW_SLOTS=10 ADDR_W=4)
modtb_set(window window_n3_p4_s6 TOP fpstereo_window SOURCES fpstereo_window.v fpstereo_ram_sdp.v
          PARAMS N=3 WORD_W=6 P=4 ROW_SLOTS=6 ADDR_W=3)
modtb_set(window window_n5_p4_s3 TOP fpstereo_window SOURCES fpstereo_window.v fpstereo_ram_sdp.v
          PARAMS N=5 WORD_W=8 P=4 ROW_SLOTS=3 ADDR_W=2)
# The window stage at P pixels a slot (G = 1), lone frames.
modtb_set(front_end front_end_n5_p1 TOP fpstereo_front_end SOURCES fpstereo_front_end.v fpstereo_window.v fpstereo_ram_sdp.v fpstereo_window_bounds.v fpstereo_slot_columns.v
          fpstereo_raster_counter.v fpstereo_frame_row.v
          PARAMS N=5 ROW_SLOTS=12 G=1 COST_ROWS=3 COST_ROW_W=2 X_W=4 Y_W=5 SIGNED_Y_W=7 G_W=1 P=1)
modtb_set(front_end front_end_n7_p2 TOP fpstereo_front_end SOURCES fpstereo_front_end.v fpstereo_window.v fpstereo_ram_sdp.v fpstereo_window_bounds.v fpstereo_slot_columns.v
          fpstereo_raster_counter.v fpstereo_frame_row.v
          PARAMS N=7 ROW_SLOTS=10 G=1 COST_ROWS=4 COST_ROW_W=2 X_W=5 Y_W=5 SIGNED_Y_W=7 G_W=1 P=2)
modtb_set(front_end front_end_n5_p2 TOP fpstereo_front_end SOURCES fpstereo_front_end.v fpstereo_window.v fpstereo_ram_sdp.v fpstereo_window_bounds.v fpstereo_slot_columns.v
          fpstereo_raster_counter.v fpstereo_frame_row.v
          PARAMS N=5 ROW_SLOTS=7 G=1 COST_ROWS=2 COST_ROW_W=1 X_W=4 Y_W=5 SIGNED_Y_W=7 G_W=1 P=2)
modtb_set(front_end front_end_n5_p4 TOP fpstereo_front_end SOURCES fpstereo_front_end.v fpstereo_window.v fpstereo_ram_sdp.v fpstereo_window_bounds.v fpstereo_slot_columns.v
          fpstereo_raster_counter.v fpstereo_frame_row.v
          PARAMS N=5 ROW_SLOTS=6 G=1 COST_ROWS=5 COST_ROW_W=3 X_W=5 Y_W=5 SIGNED_Y_W=7 G_W=1 P=4)
modtb_set(front_end front_end_n3_p4 TOP fpstereo_front_end SOURCES fpstereo_front_end.v fpstereo_window.v fpstereo_ram_sdp.v fpstereo_window_bounds.v fpstereo_slot_columns.v
          fpstereo_raster_counter.v fpstereo_frame_row.v
          PARAMS N=3 ROW_SLOTS=5 G=1 COST_ROWS=2 COST_ROW_W=1 X_W=5 Y_W=5 SIGNED_Y_W=7 G_W=1 P=4)
modtb_set(path_lanes path_lanes_uf4 TOP fpstereo_path_lanes SOURCES fpstereo_path_lanes.v
          PARAMS UF=4 COST_W=6 PATH_W=8)
modtb_set(path_lanes path_lanes_uf1 TOP fpstereo_path_lanes SOURCES fpstereo_path_lanes.v
          PARAMS UF=1 COST_W=4 PATH_W=6)
modtb_set(path_lanes path_lanes_uf8 TOP fpstereo_path_lanes SOURCES fpstereo_path_lanes.v
          PARAMS UF=8 COST_W=5 PATH_W=9)
modtb_set(sum_tree sum_tree_n7_comb TOP fpstereo_sum_tree SOURCES fpstereo_sum_tree.v
          PARAMS N=7 IN_W=9 SUM_W=12 REGISTER_LEVEL=0)
modtb_set(sum_tree sum_tree_n13_l1 TOP fpstereo_sum_tree SOURCES fpstereo_sum_tree.v
          PARAMS N=13 IN_W=8 SUM_W=10 REGISTER_LEVEL=1)
modtb_set(sum_tree sum_tree_n8_l3 TOP fpstereo_sum_tree SOURCES fpstereo_sum_tree.v
          PARAMS N=8 IN_W=5 SUM_W=8 REGISTER_LEVEL=3)
modtb_set(sum_tree sum_tree_n1 TOP fpstereo_sum_tree SOURCES fpstereo_sum_tree.v
          PARAMS N=1 IN_W=4 SUM_W=6 REGISTER_LEVEL=0)
modtb_set(subpixel_fit subpixel_fit_k4_equiangular TOP fpstereo_subpixel_fit SOURCES fpstereo_subpixel_fit.v
          PARAMS DMAX=64 DISP_W=6 SUM_W=10 K=4 EQUIANGULAR=1 OUT_W=10)
modtb_set(subpixel_fit subpixel_fit_k1_parabola TOP fpstereo_subpixel_fit SOURCES fpstereo_subpixel_fit.v
          PARAMS DMAX=64 DISP_W=6 SUM_W=10 K=1 EQUIANGULAR=0 OUT_W=7)
modtb_set(subpixel_fit subpixel_fit_k5_d256 TOP fpstereo_subpixel_fit SOURCES fpstereo_subpixel_fit.v
          PARAMS DMAX=256 DISP_W=8 SUM_W=14 K=5 EQUIANGULAR=1 OUT_W=13)
modtb_set(subpixel_fit subpixel_fit_k3_parabola_d16 TOP fpstereo_subpixel_fit SOURCES fpstereo_subpixel_fit.v
          PARAMS DMAX=16 DISP_W=4 SUM_W=6 K=3 EQUIANGULAR=0 OUT_W=7)
modtb_set(speckle speckle_w32_s6_r2 TOP fpstereo_speckle SOURCES fpstereo_speckle.v fpstereo_ram_sdp.v fpstereo_ram_tdp.v
          PARAMS W=32 S=6 R=2 WORD_W=8)
modtb_set(speckle speckle_w17_s13_r0 TOP fpstereo_speckle SOURCES fpstereo_speckle.v fpstereo_ram_sdp.v fpstereo_ram_tdp.v
          PARAMS W=17 S=13 R=0 WORD_W=12)
modtb_set(speckle speckle_w24_s1_r1 TOP fpstereo_speckle SOURCES fpstereo_speckle.v fpstereo_ram_sdp.v fpstereo_ram_tdp.v
          PARAMS W=24 S=1 R=1 WORD_W=6)
# Gap interpolation at one, two and four words a slot (docs/ppc-hardware.md): run-time widths of
# whole slots up to W.
set(MODTB_GAP_SOURCES fpstereo_gap_fill.v fpstereo_ram_sdp.v fpstereo_delay.v)
modtb_set(gap_fill gap_fill_w16_p1 TOP fpstereo_gap_fill SOURCES ${MODTB_GAP_SOURCES}
          PARAMS W=16 WORD_W=8 X_W=5 Y_W=6 P=1)
modtb_set(gap_fill gap_fill_w24_p2 TOP fpstereo_gap_fill SOURCES ${MODTB_GAP_SOURCES}
          PARAMS W=24 WORD_W=9 X_W=5 Y_W=6 P=2)
modtb_set(gap_fill gap_fill_w32_p4 TOP fpstereo_gap_fill SOURCES ${MODTB_GAP_SOURCES}
          PARAMS W=32 WORD_W=6 X_W=6 Y_W=6 P=4)
# The linear fill: whole pixels and sixteenths, one, two and four words a slot.
modtb_set(gap_fill gap_fill_linear_w16_p1 TOP fpstereo_gap_fill SOURCES ${MODTB_GAP_SOURCES}
          PARAMS W=16 WORD_W=8 X_W=5 Y_W=6 P=1 LINEAR=1 UNIT_LOG=0)
modtb_set(gap_fill gap_fill_linear_w24_p2 TOP fpstereo_gap_fill SOURCES ${MODTB_GAP_SOURCES}
          PARAMS W=24 WORD_W=12 X_W=5 Y_W=6 P=2 LINEAR=1 UNIT_LOG=4)
modtb_set(gap_fill gap_fill_linear_w32_p4 TOP fpstereo_gap_fill SOURCES ${MODTB_GAP_SOURCES}
          PARAMS W=32 WORD_W=6 X_W=6 Y_W=6 P=4 LINEAR=1 UNIT_LOG=1)
# Strips of aggregation (docs/ppc-hardware.md): two strips of one chain's latency; four, the last
# one narrower than the others; two at uf 32 (K = 6) with the 0 and 135-degree paths only.
set(MODTB_STRIP_SOURCES fpstereo_strip_aggregation.v fpstereo_aggregator.v fpstereo_delay.v fpstereo_frame_row.v
    fpstereo_ram_sdp.v fpstereo_ram_async.v fpstereo_path_lanes.v fpstereo_path_minimum.v fpstereo_min_tree.v
    fpstereo_reduction_tree.v fpstereo_unique_join.v)
# The RAMs' rows (16) hold a whole frame, so that addresses and slots name the rows.
set(MODTB_STRIP_COMMON COST_W=5 COST_MAX=24 PATH_W=8 SUM_W=10 LEVELS_PER_STAGE=2 OUT_ROWS=16 OUT_ROW_W=4
    COST_ROWS=16 COST_ROW_W=4 Y_W=6 K_W=3 COST_AW=9)
modtb_set(strip_aggregation strip_aggregation_p2 TOP fpstereo_strip_aggregation SOURCES ${MODTB_STRIP_SOURCES}
          PARAMS P=2 W=40 ROW_SLOTS=20 K=5 SEGMENT=4 UF=16 PATH_TREE_LAT=2 PATHS=15 X_W=6 COST_LEAD=1
          ${MODTB_STRIP_COMMON})
modtb_set(strip_aggregation strip_aggregation_p4 TOP fpstereo_strip_aggregation SOURCES ${MODTB_STRIP_SOURCES}
          PARAMS P=4 W=64 ROW_SLOTS=20 K=5 SEGMENT=4 UF=16 PATH_TREE_LAT=2 PATHS=15 X_W=7 COST_LEAD=1
          ${MODTB_STRIP_COMMON})
modtb_set(strip_aggregation strip_aggregation_p2_uf32_paths9 TOP fpstereo_strip_aggregation
          SOURCES ${MODTB_STRIP_SOURCES}
          PARAMS P=2 W=48 ROW_SLOTS=24 K=6 SEGMENT=4 UF=32 PATH_TREE_LAT=3 PATHS=9 X_W=6 COST_LEAD=1
          ${MODTB_STRIP_COMMON})
# With code entries: 12-bit census codes, the costs from each strip's chain cost stage (2 + the
# lanes' 2 steps after the address).
set(MODTB_STRIP_CODES_SOURCES ${MODTB_STRIP_SOURCES} fpstereo_chain_cost.v fpstereo_point_lanes.v
    fpstereo_cost_lanes.v fpstereo_fused_term.v)
modtb_set(strip_aggregation strip_aggregation_codes_p2 TOP fpstereo_strip_aggregation
          SOURCES ${MODTB_STRIP_CODES_SOURCES}
          PARAMS P=2 W=40 ROW_SLOTS=20 K=5 SEGMENT=4 UF=16 PATH_TREE_LAT=2 PATHS=15 X_W=6 CODES=1 CODE_W=12
          COST_LEAD=4 ${MODTB_STRIP_COMMON})
modtb_set(strip_aggregation strip_aggregation_codes_p4 TOP fpstereo_strip_aggregation
          SOURCES ${MODTB_STRIP_CODES_SOURCES}
          PARAMS P=4 W=64 ROW_SLOTS=20 K=5 SEGMENT=4 UF=16 PATH_TREE_LAT=2 PATHS=15 X_W=7 CODES=1 CODE_W=12
          COST_LEAD=4 ${MODTB_STRIP_COMMON})
# ... with LR1's match side per strip: Dm of every match pixel, the state handed on at the edges.
modtb_set(strip_aggregation strip_aggregation_lr1_p2 TOP fpstereo_strip_aggregation
          SOURCES ${MODTB_STRIP_CODES_SOURCES} fpstereo_lr1_match.v
          PARAMS P=2 W=40 ROW_SLOTS=20 K=5 SEGMENT=4 UF=16 PATH_TREE_LAT=2 PATHS=15 X_W=6 CODES=1 CODE_W=12
          COST_LEAD=4 LR1=1 LR1_AW=9 ${MODTB_STRIP_COMMON})
modtb_set(strip_aggregation strip_aggregation_lr1_p4 TOP fpstereo_strip_aggregation
          SOURCES ${MODTB_STRIP_CODES_SOURCES} fpstereo_lr1_match.v
          PARAMS P=4 W=64 ROW_SLOTS=20 K=5 SEGMENT=4 UF=16 PATH_TREE_LAT=2 PATHS=15 X_W=7 CODES=1 CODE_W=12
          COST_LEAD=4 LR1=1 LR1_AW=9 ${MODTB_STRIP_COMMON})
# The code entries through the strips' code RAMs, (p + 1) * K rows each, written a slot of P
# pixels a step (the row slot modulo SLOT_ROWS, a multiple of every strip's rows).
set(MODTB_STRIP_RAM_COMMON COST_W=5 COST_MAX=24 PATH_W=8 SUM_W=10 LEVELS_PER_STAGE=2 OUT_ROWS=16 OUT_ROW_W=4
    COST_ROWS=16 Y_W=6 K_W=3 COST_AW=9 CODES=1 CODE_W=12 COST_LEAD=4 RAM=1)
modtb_set(strip_aggregation strip_aggregation_ram_p2 TOP fpstereo_strip_aggregation
          SOURCES ${MODTB_STRIP_CODES_SOURCES} fpstereo_strip_code_reorder.v
          PARAMS P=2 W=40 ROW_SLOTS=20 K=5 SEGMENT=4 UF=16 PATH_TREE_LAT=2 PATHS=15 X_W=6 COST_ROW_W=4
          SLOT_ROWS=10 SLOT_W=4 ${MODTB_STRIP_RAM_COMMON})
# ... and on through a winner-take-all per strip and the strips' disparity RAMs ((P - p) * K + 1
# rows each) to the raster order, a slot of P pixels a step.
set(MODTB_STRIP_OUT_SOURCES ${MODTB_STRIP_CODES_SOURCES} fpstereo_strip_code_reorder.v
    fpstereo_strip_disparity_reorder.v fpstereo_wta.v)
modtb_set(strip_aggregation strip_aggregation_out_p2 TOP fpstereo_strip_aggregation
          SOURCES ${MODTB_STRIP_OUT_SOURCES}
          PARAMS P=2 W=40 ROW_SLOTS=20 K=5 SEGMENT=4 UF=16 PATH_TREE_LAT=2 PATHS=15 X_W=6 COST_ROW_W=4
          SLOT_ROWS=10 SLOT_W=4 OUTPUT=1 DISP_W=4 WTA_TREE_LAT=2 COST_W=5 COST_MAX=24 PATH_W=8 SUM_W=10
          LEVELS_PER_STAGE=2 OUT_ROWS=16 OUT_ROW_W=4 COST_ROWS=16 Y_W=6 K_W=3 COST_AW=9 CODES=1 CODE_W=12
          COST_LEAD=4 RAM=1)
modtb_set(strip_aggregation strip_aggregation_out_p4 TOP fpstereo_strip_aggregation
          SOURCES ${MODTB_STRIP_OUT_SOURCES}
          PARAMS P=4 W=64 ROW_SLOTS=20 K=5 SEGMENT=4 UF=16 PATH_TREE_LAT=2 PATHS=15 X_W=7 COST_ROW_W=5
          SLOT_ROWS=60 SLOT_W=6 OUTPUT=1 DISP_W=4 WTA_TREE_LAT=2 COST_W=5 COST_MAX=24 PATH_W=8 SUM_W=10
          LEVELS_PER_STAGE=2 OUT_ROWS=16 OUT_ROW_W=5 COST_ROWS=16 Y_W=6 K_W=3 COST_AW=9 CODES=1 CODE_W=12
          COST_LEAD=4 RAM=1)
# ... and with LR1 on to the left-right check at P words a slot (fpstereo_strip_lr_check: the
# strips' completed pixels banked by strip, a copy per word).
modtb_set(strip_aggregation strip_aggregation_lr1_out_p2 TOP fpstereo_strip_aggregation
          SOURCES ${MODTB_STRIP_OUT_SOURCES} fpstereo_lr1_match.v fpstereo_strip_lr_check.v fpstereo_strip_match_lookup.v
          PARAMS P=2 W=40 ROW_SLOTS=20 K=5 SEGMENT=4 UF=16 PATH_TREE_LAT=2 PATHS=15 X_W=6 COST_ROW_W=4
          SLOT_ROWS=10 SLOT_W=4 OUTPUT=1 DISP_W=4 WTA_TREE_LAT=2 COST_W=5 COST_MAX=24 PATH_W=8 SUM_W=10
          LEVELS_PER_STAGE=2 OUT_ROWS=16 OUT_ROW_W=4 COST_ROWS=16 Y_W=6 K_W=3 COST_AW=9 CODES=1 CODE_W=12
          COST_LEAD=4 RAM=1 LR1=1 LR1_AW=8 LR1_LAG=4)
modtb_set(strip_aggregation strip_aggregation_lr1_out_p4 TOP fpstereo_strip_aggregation
          SOURCES ${MODTB_STRIP_OUT_SOURCES} fpstereo_lr1_match.v fpstereo_strip_lr_check.v fpstereo_strip_match_lookup.v
          PARAMS P=4 W=64 ROW_SLOTS=20 K=5 SEGMENT=4 UF=16 PATH_TREE_LAT=2 PATHS=15 X_W=7 COST_ROW_W=5
          SLOT_ROWS=60 SLOT_W=6 OUTPUT=1 DISP_W=4 WTA_TREE_LAT=2 COST_W=5 COST_MAX=24 PATH_W=8 SUM_W=10
          LEVELS_PER_STAGE=2 OUT_ROWS=16 OUT_ROW_W=5 COST_ROWS=16 Y_W=6 K_W=3 COST_AW=9 CODES=1 CODE_W=12
          COST_LEAD=4 RAM=1 LR1=1 LR1_AW=9 LR1_LAG=4)
modtb_set(strip_aggregation strip_aggregation_ram_p4 TOP fpstereo_strip_aggregation
          SOURCES ${MODTB_STRIP_CODES_SOURCES} fpstereo_strip_code_reorder.v
          PARAMS P=4 W=64 ROW_SLOTS=20 K=5 SEGMENT=4 UF=16 PATH_TREE_LAT=2 PATHS=15 X_W=7 COST_ROW_W=5
          SLOT_ROWS=60 SLOT_W=6 ${MODTB_STRIP_RAM_COMMON})
# One aggregator (one strip) over a row of G groups: all four raster paths; three of them with
# their P2 fields in the words; the 180-degree path (MIRROR) without and with the 0-degree P2
# field, at G 4, 2 and 1 (K 5 for the minimum's latency).
set(MODTB_AGGREGATOR_SOURCES fpstereo_aggregator.v fpstereo_delay.v fpstereo_frame_row.v fpstereo_ram_sdp.v
    fpstereo_ram_async.v fpstereo_path_lanes.v fpstereo_path_minimum.v fpstereo_min_tree.v
    fpstereo_reduction_tree.v fpstereo_unique_join.v)
set(MODTB_AGGREGATOR_COMMON COST_W=5 COST_MAX=24 PATH_W=8 SUM_W=10 LEVELS_PER_STAGE=2 OUT_ROWS=16 OUT_ROW_W=4
    COST_ROWS=16 COST_ROW_W=4 Y_W=5)
modtb_set(aggregator aggregator_paths15_k2_g4 TOP fpstereo_aggregator SOURCES ${MODTB_AGGREGATOR_SOURCES}
          PARAMS W=20 ROW_SLOTS=20 K=2 SEGMENT=10 G=4 UF=4 PATHS=15 PENALTIES=0 PATH_TREE_LAT=1 X_W=5 G_W=2 K_W=1
          COST_AW=11 MIRROR=0 ${MODTB_AGGREGATOR_COMMON})
modtb_set(aggregator aggregator_paths13_p2_fields_k3_g2 TOP fpstereo_aggregator SOURCES ${MODTB_AGGREGATOR_SOURCES}
          PARAMS W=21 ROW_SLOTS=21 K=3 SEGMENT=7 G=2 UF=8 PATHS=13 PENALTIES=3 PATH_TREE_LAT=2 X_W=5 G_W=1 K_W=2
          COST_AW=10 MIRROR=0 ${MODTB_AGGREGATOR_COMMON})
modtb_set(aggregator aggregator_mirror_k2_g4 TOP fpstereo_aggregator SOURCES ${MODTB_AGGREGATOR_SOURCES}
          PARAMS W=19 ROW_SLOTS=20 K=2 SEGMENT=10 G=4 UF=4 PATHS=1 PENALTIES=0 PATH_TREE_LAT=1 X_W=5 G_W=2 K_W=1
          COST_AW=11 MIRROR=1 ${MODTB_AGGREGATOR_COMMON})
modtb_set(aggregator aggregator_mirror_p2_fields_k3_g2 TOP fpstereo_aggregator SOURCES ${MODTB_AGGREGATOR_SOURCES}
          PARAMS W=21 ROW_SLOTS=21 K=3 SEGMENT=7 G=2 UF=8 PATHS=1 PENALTIES=2 PATH_TREE_LAT=2 X_W=5 G_W=1 K_W=2
          COST_AW=10 MIRROR=1 ${MODTB_AGGREGATOR_COMMON})
modtb_set(aggregator aggregator_mirror_p2_field_k5_g1 TOP fpstereo_aggregator SOURCES ${MODTB_AGGREGATOR_SOURCES}
          PARAMS W=20 ROW_SLOTS=20 K=5 SEGMENT=4 G=1 UF=16 PATHS=1 PENALTIES=1 PATH_TREE_LAT=2 X_W=5 G_W=1 K_W=3
          COST_AW=9 MIRROR=1 ${MODTB_AGGREGATOR_COMMON})
