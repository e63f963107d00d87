#pragma once
// The corpus (bench/corpus) as the text of one job file: generic, mm,
// 0.01 mm, one Bézier entity per curve (the first `most`).
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

inline std::string corpus_job_text(const nlohmann::json& doc, size_t most) {
  std::string text =
      "{\"bezcam\": 1, \"units\": \"mm\", \"tolerance\": 0.01, \"machine\": \"generic\", \"entities\": [";
  char buf[96];
  const auto& curves = doc["curves"];
  for (size_t i = 0; i < curves.size() && i < most; ++i) {
    text += i ? ",\n" : "\n";
    text += "{\"type\": \"bezier\", \"points\": [";
    for (size_t k = 0; k < curves[i].size(); ++k) {
      std::snprintf(buf, sizeof buf, "%s[%.17g, %.17g]", k ? ", " : "", curves[i][k][0].get<double>(),
                    curves[i][k][1].get<double>());
      text += buf;
    }
    text += "]}";
  }
  text += "]}\n";
  return text;
}
