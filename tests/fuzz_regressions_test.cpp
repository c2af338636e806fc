// Replays every input kept in tests/fuzz_regressions/ through the fuzzer's
// pipeline: each must finish or throw fixel::Error (never crash or throw
// anything else).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "../fuzz/pipeline.h"

namespace fixel {
namespace {

TEST(FuzzRegressions, EveryKeptInputIsHandledCleanly) {
  const std::filesystem::path dir = std::filesystem::path(FIXEL_SOURCE_DIR) / "tests" / "fuzz_regressions";
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    try {
      fuzz::run_pipeline(text.str());
    } catch (const Error&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << entry.path() << ": " << e.what();
    }
    ++replayed;
  }
  EXPECT_GE(replayed, 6);
}

}  // namespace
}  // namespace fixel
