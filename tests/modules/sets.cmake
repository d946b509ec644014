# The parameter sets of the per-module tests: modtb_set(<bench> <test name> TOP ... SOURCES ...
# PARAMS ...), see CMakeLists.txt. Test names are ctest's modules_<name>.
modtb_set(min_tree min_tree_n8_l3 TOP fpstereo_min_tree SOURCES fpstereo_min_tree.v
          PARAMS N=8 W=8 IDX_W=3 LEVELS_PER_STAGE=3)
modtb_set(min_tree min_tree_n13_l1 TOP fpstereo_min_tree SOURCES fpstereo_min_tree.v
          PARAMS N=13 W=5 IDX_W=4 LEVELS_PER_STAGE=1)
modtb_set(min_tree min_tree_n6_l2 TOP fpstereo_min_tree SOURCES fpstereo_min_tree.v
          PARAMS N=6 W=3 IDX_W=3 LEVELS_PER_STAGE=2)
modtb_set(unique_tree unique_tree_n8_l3 TOP fpstereo_unique_tree
          SOURCES fpstereo_unique_tree.v fpstereo_unique_join.v PARAMS N=8 W=10 IDX_W=3 LEVELS_PER_STAGE=3)
modtb_set(unique_tree unique_tree_n13_l2 TOP fpstereo_unique_tree
          SOURCES fpstereo_unique_tree.v fpstereo_unique_join.v PARAMS N=13 W=4 IDX_W=4 LEVELS_PER_STAGE=2)
modtb_set(unique_tree unique_tree_n3_l1 TOP fpstereo_unique_tree
          SOURCES fpstereo_unique_tree.v fpstereo_unique_join.v PARAMS N=3 W=3 IDX_W=2 LEVELS_PER_STAGE=1)
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
