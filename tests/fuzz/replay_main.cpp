// Replays inputs through a fuzz target without libFuzzer, as the normal suite runs them: every file under
// the folders given (seed corpora and the crash inputs found by past campaigns, tests/fuzz/regressions/),
// each once. A finding aborts, as under the fuzzer; otherwise prints how many inputs ran and exits 0.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
  std::size_t count = 0;
  for (int i = 1; i < argc; ++i) {
    const std::filesystem::path folder = argv[i];
    if (!std::filesystem::is_directory(folder)) continue;  // a target without regressions yet
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
      if (!entry.is_regular_file()) continue;
      std::ifstream in(entry.path(), std::ios::binary);
      const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
      ++count;
    }
  }
  if (count == 0) {
    std::fprintf(stderr, "replay: no inputs under the folders given\n");
    return 1;
  }
  std::printf("replay: %zu inputs, each a result or a one-line input error\n", count);
  return 0;
}
