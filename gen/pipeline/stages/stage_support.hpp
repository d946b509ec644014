// What several stages share: the start flag of a stage with a schedule of its own,
// the stream nets, the aggregator's parameters and memories (the base side's and LR2's match
// side's), the output registers (the disparity's and the right view's).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core_builder.hpp"
#include "plan.hpp"

namespace fpstereo::rtl {

// The stage's first step as a localparam, and `flag`, a register high from that step on (a
// compare with the step counter would lie on the path to every enable the flag gates).
void start_flag(CoreBuilder& core, const RtlDesign& d, const Stage& stage, const std::string& flag);

// A pixel stream's nets, the word word_bits wide (the output word's by default).
void stream_wires(CoreBuilder& core, const RtlDesign& d, const PixelStream& s, int word_bits = 0);

// A stage's pixel stream in and out, as the connections of in_x, in_y, in_word, out_event, out_x,
// out_y and out_word (the median's and gap interpolation's ports).
Connections stream_connections(const PixelStream& in, const PixelStream& out);

// The nets of the words in chain order named `words`: _group, _active, _x, _slot, a _word of
// word_bits and, with_whole, the whole D (_whole).
void word_wires(CoreBuilder& core, const Geometry& g, const std::string& words, int word_bits, bool with_whole);
// Their position as one tag: {_active, _x, _slot}, with_group _group, then the extra nets.
std::string word_tag(const std::string& words, bool with_group, const std::vector<std::string>& extra = {});

// The window stage's centre lag in slots (with strips, the windows of a slot's P pixels lag
// ceil(r / P) slots) and the columns of its window arrays (fpstereo_front_end's COLS: P windows
// side by side, pixel q's in columns q to q + N - 1).
int window_centre_lag(const Geometry& g);
int window_columns(const Geometry& g);

// With min-disp m below 0, the slots a base pixel x waits for the slot holding its match pixel
// x - m: ceil(-m / P); 0 for m >= 0.
int min_disp_wait_slots(const Geometry& g, int min_disp);

// With a code reorder, min_disp_wait_slots: a slot's base entries (where they go, their penalties)
// wait that long, fpstereo_code_reorder's -MIN_DISP at P = 1 and fpstereo_strip_code_reorder's
// BASE_WAIT; the aggregation reads that much later. 0 otherwise.
// With min_disp, as the code entries of LR2's match side in strips have (below).
int code_base_wait_slots(const Geometry& g);
int code_base_wait_slots(const Geometry& g, int min_disp);

// LR2's match side in strips is a base side over the match image (docs/ppc-hardware.md, "LR2 in
// strips"): its entries are the base side's with base and match swapped, and match pixel x' at
// index d pairs with base pixel x' + m + d, which is x' - m' - (dmax - 1 - d) for
// m' = -(m + dmax - 1), its min-disp, its lanes the indices from dmax - 1 down.
int lr2_match_min_disp(const Geometry& g);

// In strips, the steps LR1's writes wait so that they land with the strips' disparity words: the
// winner's, the sub-pixel fit's and the confidence's latencies (fpstereo_strip_aggregation's
// LR1_LAG).
int strip_lr1_lag(const Geometry& g);

// LR2's match side's schedule in strips after the base side's, in steps (negative where earlier):
// its entries' (or its window costs') wait below its min-disp less the base side's, and less the
// base side's code writes' wait for adaptive P2's penalties, which the match side does without
// (its reads follow its writes as closely as the base side's do theirs: a strip's last word is
// overwritten K steps after it is due where SEG = P).
int lr2_schedule_lead(const Geometry& g);

// In strips, the slots the left-right check's lookups wait (fpstereo_strip_lr_check's VIEW_WAIT).
// LR1 with the right view and min-disp m above 0: Dm(x) is completed m pixels further right than
// anything the check looks up from x, so ceil(m / P). LR2: the steps by which the match side's
// writes land after the base side's words (lr2_dm_lag). 0 otherwise.
int check_wait_slots(const Geometry& g);

// LR2's match side in strips: the steps its winners' writes wait (fpstereo_strip_aggregation's
// DM_LAG), so that they land with the base side's words where the match side's schedule is not
// later than the base side's.
int lr2_dm_lag(const Geometry& g);

// With min-disp m below 0, the match entries a row's first pixel needs left of its own match pixel
// -m: min(-m, dmax - 1) of them, fpstereo_chain_cost's PREFIX (the cost reorder stage holds them).
int chain_prefix_entries(const Geometry& g);
int chain_prefix_entries(const Geometry& g, int min_disp);

// `net`'s field of `bits` bits from bit `lsb`: "net[lsb + bits - 1:lsb]".
std::string bit_field(const std::string& net, int64_t lsb, int64_t bits);
// "{part(count - 1), ..., part(0)}": fields side by side, part(0) in the lowest bits (with strips,
// a slot's P pixels' nets, pixel 0 lowest).
std::string concat_high_to_low(int count, const std::function<std::string(int)>& part);

// With strips and the confidence, the strips' disparity RAMs' words, each with its confidence
// above it, as fpstereo_strip_aggregation reads them (the disparity reorder stage splits them).
constexpr const char* kStripConfidentWords = "strip_read_words";

// The aggregator's memories below scope (fpstereo_aggregator.v), over a row of `pixels` (a strip's,
// or by default the whole width), and its parameters but MATCH_SIDE, which LR2's match side sets
// itself.
std::vector<StageMemory> aggregator_memories(const Geometry& g, const std::string& scope, int pixels = 0);
Connections aggregator_parameters(const RtlDesign& d);
// ... and those of the 180-degree path's mirrored one (fpstereo_right_to_left), which sets its
// sums' width, its one path and its output rows itself.
Connections mirror_aggregator_parameters(const RtlDesign& d);

// fpstereo_strip_aggregation's parameters that the base side and LR2's match side share: the
// strips, the aggregators' (but the groups: G = 1 in strips), the fused cost's, the code entries'
// and their RAMs'.
Connections strip_aggregation_parameters(const RtlDesign& d);
// A pixel's entry in a strip's RAM: its base and match code entries (with adaptive P2's
// penalties), or SAD's and ZSAD's cost word (with them).
int64_t strip_entry_bits(const Geometry& g);
// LR2's match side's entry in its strips' RAMs: the same without penalties (it has none).
int64_t lr2_strip_entry_bits(const Geometry& g);
// The address bits of a strip's match-side Dm writes (strip 0's, the most: (P * K + 1) * R words).
int strip_dm_address_bits(const Geometry& g);

// The fused cost's parameters of the cost lanes (fpstereo_point_lanes and the stages around it):
// WEIGHT, TRUNC, FEATURE_W and GRADIENT; none without the fused cost (the templates' defaults).
Connections fused_cost_parameters(const Geometry& g);

// An output register: the stream's word with its first and last flags, pushed in the step after
// `event` (the sequencer stalls while the output register slice is full). `prefix`_due is the
// sequencer's input; the core's ports are `prefix`_push, _word, _first and _last.
void output_register(CoreBuilder& core, const std::string& prefix, const PixelStream& stream, const std::string& event,
                     const std::string& word, int word_bits);

// The HLS loop of a window of radius r: its centre lags the input by r rows and r pixels.
HlsLoop hls_window_loop(const Geometry& g, const std::string& what, int r);

}  // namespace fpstereo::rtl
