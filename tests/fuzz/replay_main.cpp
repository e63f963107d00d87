// Replays inputs through a fuzz target without libFuzzer, so that the
// normal and the sanitizer builds run it under ctest (FuzzReplay.*): every
// finding kept in tests/fuzz/regressions/<target>/ and every seed given
// stays fixed. A finding is a crash, a sanitizer report or the target's own
// __builtin_trap(); a refusal is a correct answer.
//
//   replay_TARGET [--ext=.json] PATH...
//
// PATH: a file, or a directory whose files (sorted by name, not recursing)
// are replayed, but for hidden files and READMEs; --ext keeps only the files of a directory ending so (for
// the arguments after it). Prints how many inputs ran; exits 1 when none.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::string ext;
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--ext=", 0) == 0) {
      ext = a.substr(6);
      continue;
    }
    if (fs::is_directory(a)) {
      std::vector<fs::path> in;
      for (const auto& e : fs::directory_iterator(a)) {
        const std::string name = e.path().filename().string();
        if (name.starts_with(".") || name.starts_with("README")) continue;  // .keep, notes
        if (e.is_regular_file() && (ext.empty() || name.ends_with(ext))) in.push_back(e.path());
      }
      std::sort(in.begin(), in.end());
      files.insert(files.end(), in.begin(), in.end());
    } else if (fs::is_regular_file(a)) {
      files.emplace_back(a);
    } else {
      std::fprintf(stderr, "replay: %s: no such file or directory\n", a.c_str());
      return 1;
    }
  }
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::fprintf(stderr, "replay: %s\n", f.c_str());  // the last one named is the culprit of a crash
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(data.data()), data.size());
  }
  std::printf("replay: %zu inputs, no finding\n", files.size());
  return files.empty() ? 1 : 0;
}
