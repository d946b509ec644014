// Text helpers of the HLS backend that the stages' kernel calls share.
#pragma once

#include <string>
#include <vector>

namespace fpstereo::hls {

// `hls::stream<type> a("a"), b("b");`, with a FIFO depth pragma per stream when given.
inline std::string stream_declarations(const std::string& type, const std::vector<std::string>& names,
                                       const std::string& depth = "") {
  std::string text = "  hls::stream<" + type + "> ";
  for (size_t i = 0; i < names.size(); ++i) text += (i ? ", " : "") + names[i] + "(\"" + names[i] + "\")";
  text += ";\n";
  if (!depth.empty())
    for (const auto& name : names) text += "#pragma HLS STREAM variable = " + name + " depth = " + depth + "\n";
  return text;
}

}  // namespace fpstereo::hls
