// InputError's message: "field: value reason", with a value or reason of
// thousands of characters shown by its ends.
#include "fixel/error.h"

#include <gtest/gtest.h>

#include <string>

namespace fixel {
namespace {

// Whether s is well-formed UTF-8 (lead byte, then its continuation bytes).
bool valid_utf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const int n = c < 0x80 ? 0 : (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xE ? 2 : (c >> 3) == 0x1E ? 3 : -1;
    if (n < 0 || i + n >= s.size() + (n == 0 ? 1 : 0)) return false;
    for (int k = 1; k <= n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return false;
    i += n + 1;
  }
  return true;
}

GTEST_TEST(InputError, AShortMessageIsFieldValueAndReason) {
  EXPECT_STREQ(InputError("fixels[0].gap", "-1", "must be >= 0").what(), "fixels[0].gap: -1 must be >= 0");
  EXPECT_STREQ(InputError("scene.json", "", "cannot be opened").what(), "scene.json: cannot be opened");
}

GTEST_TEST(InputError, AValueOfThousandsOfDigitsIsShownByItsEndsAndKeptWhole) {
  const std::string value = "1" + std::string(10000, '0') + "7";
  const InputError e("body.mass", value, "is too large");
  const std::string message = e.what();
  EXPECT_EQ(e.value(), value);
  EXPECT_LT(message.size(), 900u);
  EXPECT_EQ(message.rfind("body.mass: 1" + std::string(599, '0') + "…[", 0), 0u) << message;
  EXPECT_NE(message.find("…[9202 bytes]…" + std::string(199, '0') + "7 is too large"), std::string::npos) << message;
}

// A long file path is what the user needs whole, to find the file.
GTEST_TEST(InputError, AValueOfUpTo864BytesIsShownWhole) {
  const std::string path = "/" + std::string(863, 'p');
  EXPECT_EQ(std::string(InputError("--svg", path, "cannot be written").what()),
            "--svg: " + path + " cannot be written");
  const std::string longer = path + "q";
  EXPECT_NE(std::string(InputError("--svg", longer, "cannot be written").what()).find(" bytes]…"), std::string::npos);
}

// A newline in a file name must not start a line of its own in the message.
GTEST_TEST(InputError, ControlCharactersAreShownEscapedAndKeptWhole) {
  const std::string path = std::string("a\nfixel: error: b\tc\r") + '\x01' + '\x7f' + ".json";
  const InputError e("--svg", path, "cannot be written: no such folder " + path);
  EXPECT_EQ(std::string(e.what()),
            "--svg: a\\nfixel: error: b\\tc\\r\\x01\\x7f.json cannot be written: no such folder "
            "a\\nfixel: error: b\\tc\\r\\x01\\x7f.json");
  EXPECT_EQ(e.value(), path);
  EXPECT_STREQ(InputError("x", "μ ≈ 1", "").what(), "x: μ ≈ 1");  // UTF-8 is not escaped
}

GTEST_TEST(InputError, AShortenedMessageCutsBetweenCharacters) {
  std::string reason;
  for (int k = 0; k < 2000; ++k) reason += k % 3 ? "μ" : "≈";  // two- and three-byte characters
  const std::string message = InputError("x", "", reason).what();
  EXPECT_LT(message.size(), reason.size());
  EXPECT_TRUE(valid_utf8(message));
  EXPECT_TRUE(valid_utf8(reason));  // the check itself accepts what it should
  EXPECT_FALSE(valid_utf8(reason.substr(0, 1)));
}

}  // namespace
}  // namespace fixel
