#include "output_text.hpp"

#include <fmt/core.h>

#include <cctype>
#include <functional>
#include <stdexcept>

#include "hls_text.hpp"
#include "outputs.hpp"

namespace fpstereo::hls {
namespace {

using rtl::OutputStream;
using rtl::OutputWord;

// The AXI4-Stream beat of an output: its tdata width from the list (the kernels' VideoOut<C> is
// the same type for the disparity words).
std::string beat_type(const OutputStream& o) { return fmt::format("ap_axiu<{}, 1, 1, 1>", o.tdata_bits()); }

// The element of a word's frame in memory.
std::string element_type(const OutputWord& word) {
  if (word.frame_bits == 8) return "unsigned char";
  if (word.frame_bits == 16) return "unsigned short";
  throw std::logic_error("output word " + word.name + ": no C type for frames of " +
                         std::to_string(word.frame_bits) + "-bit pixels");
}

// The test bench's and host program's name of a plane's encoding (fpstereo_hls_io.hpp).
std::string encoding_name(PlaneEncoding e) {
  switch (e) {
    case PlaneEncoding::Disparities:
      return "Encoding::Disparities";
    case PlaneEncoding::WholeDisparities:
      return "Encoding::WholeDisparities";
    case PlaneEncoding::Levels:
      return "Encoding::Levels";
  }
  throw std::logic_error("encoding_name: an encoding without a name");
}

// `each(item)` joined by `separator`, over the streams or over every stream's words.
std::string join_streams(const std::vector<OutputStream>& streams, const std::string& separator,
                         const std::function<std::string(const OutputStream&)>& each) {
  std::string text;
  for (const auto& o : streams) text += (text.empty() ? "" : separator) + each(o);
  return text;
}
std::string join_words(const std::vector<OutputStream>& streams, const std::string& separator,
                       const std::function<std::string(const OutputStream&, const OutputWord&, int)>& each) {
  std::string text;
  int index = 0;
  for (const auto& o : streams)
    for (const auto& word : o.words) {
      text += (index == 0 ? "" : separator) + each(o, word, index);
      ++index;
    }
  return text;
}

// The memory-mapped wrapper's store of one output stream: each word of tdata to its own frame.
std::string store_function(const OutputStream& o, const std::string& top, const std::string& config) {
  std::string frames, stores;
  for (const auto& word : o.words) {
    frames += element_type(word) + "* " + word.frame + ", ";
    stores += fmt::format("    {}[i] = ({})(data.range({}, {}));\n", word.frame, element_type(word),
                          word.lsb + word.bits - 1, word.lsb);
  }
  return fmt::format(
      "// {0} to memory: each word of its tdata to a frame of its own.\n"
      "static void {1}_store_{0}(hls::stream<{2}>& in, {3}int width, int height) {{\n"
      "  const fpstereo_hls::Frame f = fpstereo_hls::clamp_frame<{4}>(width, height);\n"
      "store_{0}_pixels:\n"
      "  for (int i = 0; i < f.width * f.height; ++i) {{\n"
      "#pragma HLS PIPELINE II = 1\n"
      "#pragma HLS LOOP_TRIPCOUNT max = {4}::kMaxWidth * {4}::kMaxHeight\n"
      "    const ap_uint<{5}> data = in.read().data;\n"
      "{6}"
      "  }}\n"
      "}}\n\n",
      o.port, top, beat_type(o), frames, config, o.tdata_bits(), stores);
}

}  // namespace

std::map<std::string, std::string> output_text(const rtl::Geometry& g, const std::string& top,
                                               const std::string& config) {
  const std::vector<OutputStream> streams = rtl::output_streams(g);
  const int64_t pixels = int64_t(g.cfg.width) * g.cfg.height;
  std::map<std::string, std::string> vars;
  // The top functions: the pipeline's streams carry the core's names (out, view), the top's the ports'.
  vars["PIPELINE_OUTPUTS"] = join_streams(
      streams, ", ", [](const OutputStream& o) { return "hls::stream<" + beat_type(o) + ">& " + o.core; });
  vars["TOP_OUTPUTS"] = join_streams(
      streams, ", ", [](const OutputStream& o) { return "hls::stream<" + beat_type(o) + ">& " + o.port; });
  vars["OUTPUT_COMMENT"] = join_streams(streams, "", [](const OutputStream& o) {
    std::string fields;
    for (const auto& f : o.fields) fields += fmt::format(", {} [{}:{}]", f.name, f.lsb + f.bits - 1, f.lsb);
    return fmt::format("//   {}: {}, tdata {} bits{}\n", o.port, o.what, o.tdata_bits(), fields);
  });
  vars["OUTPUT_ARGUMENTS"] = join_streams(streams, ", ", [](const OutputStream& o) { return o.port; });
  vars["OUTPUT_PRAGMAS"] = join_streams(streams, "", [](const OutputStream& o) {
    return "#pragma HLS INTERFACE mode = axis port = " + o.port + "\n";
  });
  // The memory-mapped wrapper: a frame per word, each in an m_axi bundle of its own after the two
  // images' gmem0 and gmem1; its streams named as the ports, and a store per stream.
  vars["MM_FRAMES"] = join_words(streams, ", ", [](const OutputStream&, const OutputWord& word, int) {
    return element_type(word) + "* " + word.frame;
  });
  vars["MM_FRAME_PRAGMAS"] =
      join_words(streams, "", [&](const OutputStream&, const OutputWord& word, int i) {
        return fmt::format(
            "#pragma HLS INTERFACE mode = m_axi port = {0} offset = slave bundle = gmem{1} depth = {2}\n"
            "#pragma HLS INTERFACE mode = s_axilite port = {0} bundle = control\n",
            word.frame, 2 + i, pixels);
      });
  vars["MM_STREAMS"] = join_streams(
      streams, "", [](const OutputStream& o) { return stream_declarations(beat_type(o), {o.port}); });
  vars["MM_STORE_FUNCTIONS"] =
      join_streams(streams, "", [&](const OutputStream& o) { return store_function(o, top, config); });
  vars["MM_STORES"] = join_streams(streams, "", [&](const OutputStream& o) {
    std::string frames;
    for (const auto& word : o.words) frames += word.frame + ", ";
    return fmt::format("  {}_store_{}({}, {}width, height);\n", top, o.port, o.port, frames);
  });
  // The test bench and the host program: the frames in the list's order, the words first (given by
  // position), the others under their planes' `fpstereo run` options; each stream read into its
  // words' frames.
  vars["OUTPUT_FRAMES"] = join_words(streams, "", [](const OutputStream&, const OutputWord& word, int) {
    const PlaneInfo& plane = plane_info(word.plane);
    return fmt::format("    {{\"{}\", \"{}\", {}}},\n", word.frame, plane.option, encoding_name(plane.encoding));
  });
  const auto usage = [&](const char* format) {
    return join_words(streams, "", [&](const OutputStream&, const OutputWord& word, int i) -> std::string {
      if (i == 0) return "";
      const PlaneInfo& plane = plane_info(word.plane);
      std::string file = word.frame;
      for (char& c : file) c = char(std::toupper(static_cast<unsigned char>(c)));
      return (i == 1 ? "" : " ") + fmt::format(fmt::runtime(format), plane.option, file,
                                               plane.encoding == PlaneEncoding::Levels ? ".pgm" : ".pfm");
    });
  };
  vars["TB_USAGE"] = usage("{} {}{}");
  vars["HOST_USAGE"] = usage("[{} {}{}]");
  vars["TB_OUTPUT_STREAMS"] = join_streams(
      streams, "", [](const OutputStream& o) { return stream_declarations(beat_type(o), {o.port}); });
  int first_word = 0;
  vars["TB_READS"] = join_streams(streams, "", [&](const OutputStream& o) {
    std::string words;
    for (const auto& word : o.words)
      words += fmt::format("{}{{&got[{}], {}, {}}}", words.empty() ? "" : ", ", first_word++, word.lsb, word.bits);
    return fmt::format("  read_frame({0}, \"{0}\", left.width, left.height, {{{1}}}, framing_ok);\n", o.port,
                       words);
  });
  // The host program: an XRT buffer per frame (kernel arguments from 2 on), or in C-simulation the
  // frames themselves.
  vars["HOST_BUFFERS"] = join_words(streams, "", [](const OutputStream&, const OutputWord& word, int i) {
    return fmt::format("  xrt::bo {}(device, pixels * sizeof({}), kernel.group_id({}));\n", word.frame,
                       element_type(word), 2 + i);
  });
  vars["HOST_BUFFER_ARGUMENTS"] =
      join_words(streams, ", ", [](const OutputStream&, const OutputWord& word, int) { return word.frame; });
  vars["HOST_READS"] = join_words(streams, "", [](const OutputStream&, const OutputWord& word, int i) {
    return fmt::format("  {0}.sync(XCL_BO_SYNC_BO_FROM_DEVICE);\n  {0}.read(data{1}(frames[{2}]));\n",
                       word.frame, word.frame_bits, i);
  });
  vars["HOST_FRAME_POINTERS"] = join_words(
      streams, ", ",
      [](const OutputStream&, const OutputWord& word, int i) { return fmt::format("data{}(frames[{}])", word.frame_bits, i); });
  return vars;
}

}  // namespace fpstereo::hls
