// Text quoted into error messages (app/text/quoted.h): one line of well-formed UTF-8, whatever the input.
#include "app/text/quoted.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace skinlayer::text {
namespace {

TEST(Printable, KeepsWellFormedUtf8AndMarksEverythingElse) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"plain ascii", "plain ascii"},
      {"\xc3\xa9t\xc3\xa9 \xe2\x82\xac \xf0\x9d\x84\x9e",
       "\xc3\xa9t\xc3\xa9 \xe2\x82\xac \xf0\x9d\x84\x9e"},  // 2-4 bytes
      {"a\nb\tc\rd\x7f"
       "e",
       "a?b?c?d?e"},                    // control characters and DEL
      {std::string("a\0b", 3), "a?b"},  // NUL
      {"\x80x", "?x"},                  // a lone continuation byte
      {"\xc0\x80", "??"},               // an overlong NUL
      {"\xe0\x80\xaf", "???"},          // an overlong '/'
      {"\xed\xa0\x80", "???"},          // a UTF-16 surrogate, U+D800
      {"\xf4\x90\x80\x80", "????"},     // past U+10FFFF
      {"\xf5\x80", "??"},               // a lead byte no UTF-8 has
      {"\xe2\x82", "??"},               // a sequence cut short
      {"\xe2\x82x", "??x"},
  };
  for (const auto& [text, shown] : cases) EXPECT_EQ(text::printable(text), shown) << shown;
}

TEST(Quoted, CutsAtFortyBytesWithoutSplittingACharacterIntoBadUtf8) {
  EXPECT_EQ(text::quoted("abc"), "'abc'");
  const std::string long_text(39, 'x');
  const std::string cut = text::quoted(long_text + "\xc3\xa9" + "tail");  // the 40th byte is the first of a 2-byte 'é'
  EXPECT_EQ(cut, "'" + long_text + "?...'");
  EXPECT_EQ(text::printable(cut), cut);
}

}  // namespace
}  // namespace skinlayer::text
