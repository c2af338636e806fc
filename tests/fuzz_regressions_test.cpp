// Replays every input kept in tests/fuzz_regressions/ through the fuzzer's
// pipeline: each must finish or throw fixel::Error (never crash or throw
// anything else).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include "../fuzz/pipeline.h"
#include "../fuzz/structured.h"

namespace fixel {
namespace {

GTEST_TEST(FuzzRegressions, EveryKeptInputIsHandledCleanly) {
  const std::filesystem::path dir = std::filesystem::path(FIXEL_SOURCE_DIR) / "tests" / "fuzz_regressions";
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    try {
      fuzz::run_pipeline(text.str());
    } catch (const InternalError& e) {
      ADD_FAILURE() << entry.path() << ": broken invariant: " << e.what();
    } catch (const Error&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << entry.path() << ": " << e.what();
    }
    ++replayed;
  }
  EXPECT_GE(replayed, 6);
}

// The structured target's inputs (raw bytes, *.bin) and, as in its seed
// corpus, the bundled scenes' bytes.
GTEST_TEST(FuzzRegressions, EveryStructuredInputAndBundledSceneRunsCleanly) {
  std::vector<std::filesystem::path> inputs;
  for (const auto& dir : {std::filesystem::path(FIXEL_SOURCE_DIR) / "tests" / "fuzz_regressions" / "structured",
                          std::filesystem::path(FIXEL_SOURCE_DIR) / "data" / "scenes"})
    for (const auto& entry : std::filesystem::directory_iterator(dir)) inputs.push_back(entry.path());
  int ran_through = 0, operations_ran = 0;
  for (const auto& path : inputs) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
    // Each through the whole-library pipeline of the first structured target
    // and through the one-operation pipeline of today's.
    try {
      fuzz::run_structured(data, bytes.size());
      ++ran_through;
    } catch (const InternalError& e) {
      ADD_FAILURE() << path << ": broken invariant: " << e.what();
    } catch (const Error&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << path << ": " << e.what();
    }
    try {
      fuzz::run_operation(data, bytes.size());
      ++operations_ran;
    } catch (const InternalError& e) {
      ADD_FAILURE() << path << ": run_operation: broken invariant: " << e.what();
    } catch (const Error&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << path << ": run_operation: " << e.what();
    }
  }
  EXPECT_GE(inputs.size(), 10u);
  // Most inputs must get past parsing (11 and 9 of 14 today): a change that
  // made every input an early InputError would replay nothing.
  EXPECT_GE(2 * ran_through, static_cast<int>(inputs.size()));
  EXPECT_GE(2 * operations_ran, static_cast<int>(inputs.size()));
  std::cout << ran_through << " of " << inputs.size() << " structured inputs ran the whole pipeline, " << operations_ran
            << " their one operation to the end\n";
}

// The slow structured target's inputs (structured_slow/*.bin).
GTEST_TEST(FuzzRegressions, EverySlowStructuredInputRunsCleanly) {
  const std::filesystem::path dir =
      std::filesystem::path(FIXEL_SOURCE_DIR) / "tests" / "fuzz_regressions" / "structured_slow";
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    try {
      fuzz::run_operation(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), true);
    } catch (const InternalError& e) {
      ADD_FAILURE() << entry.path() << ": broken invariant: " << e.what();
    } catch (const Error&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << entry.path() << ": " << e.what();
    }
    ++replayed;
  }
  EXPECT_GE(replayed, 2);
}

// The slow set's design operation compares the filtered answer with the
// forced-exact one: its kept polygon input runs both to the end (no error,
// no stop), and the comparison tells answers apart by one exact score, one
// count or one note.
GTEST_TEST(FuzzRegressions, TheDesignInputRunsToTheEndAndItsComparisonSeesOneDifferentScore) {
  const std::filesystem::path path = std::filesystem::path(FIXEL_SOURCE_DIR) / "tests" / "fuzz_regressions" /
                                     "structured_slow" / "seed_design_polygon.bin";
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GE(bytes.size(), 2u);
  EXPECT_NO_THROW(fuzz::run_operation(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), true));

  DesignResult a;
  a.layouts.resize(2);
  a.layouts[1].score = Rational(3, 8);
  a.layouts[1].step_score = Rational(1, 4);
  a.stats.regions = 2;
  DesignResult b = a;
  EXPECT_TRUE(fuzz::same_design(a, b));
  b.layouts[1].step_score = Rational(1, 5);
  EXPECT_FALSE(fuzz::same_design(a, b));
  b = a;
  b.stats.j_empty = 1;
  EXPECT_FALSE(fuzz::same_design(a, b));
  b = a;
  b.layouts[0].note = "J undecided";
  EXPECT_FALSE(fuzz::same_design(a, b));
  b = a;
  b.layouts[0].j_width = 0.5;  // display only
  EXPECT_TRUE(fuzz::same_design(a, b));
}

}  // namespace
}  // namespace fixel
