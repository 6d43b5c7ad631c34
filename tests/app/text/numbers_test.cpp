// parse_number's rejections and the reasons error messages give for them (app/text/numbers.h).
#include "app/text/numbers.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "app/cli/csv_reader.h"
#include "app/cli/errors.h"

namespace skinlayer::text {
namespace {

TEST(NumberRejection, SaysWhetherTheTokenIsMalformedOrOutOfADoublesRange) {
  struct Case {
    std::string token;
    std::string reason;
  };
  const std::string too_large = "is too large for a double (magnitude above 1.8e308)";
  const std::string too_small = "is too small for a double (nonzero magnitude below 4.9e-324)";
  const Case cases[] = {
      {"abc", "is not a number"},
      {"1e", "is not a number"},
      {"", "is not a number"},
      {"1e-400 ", "is not a number"},  // trailing blank: malformed, whatever the value
      {"1e400", too_large},
      {"-1e309", too_large},
      {std::string(400, '9'), too_large},
      {"1e-400", too_small},
      {"-1e-400", too_small},
      {"2e-324", too_small},
      {"0." + std::string(399, '0') + "1", too_small},
  };
  for (const Case& c : cases) {
    EXPECT_FALSE(text::parse_number(c.token).has_value()) << c.token;
    EXPECT_EQ(text::number_rejection(c.token), c.reason) << c.token;
  }
}

TEST(NumberRejection, ReachesTheCsvError) {
  std::istringstream in("theta_i,theta_o,phi\n30,20,0\n30,1e-400,0\n");
  try {
    (void)cli::read_angle_rows(in);
    FAIL() << "an underflowing theta_o was accepted";
  } catch (const cli::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("line 3: theta_o"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("is too small for a double"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace skinlayer::text
