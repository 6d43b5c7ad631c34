// Fuzz-style tests of the command line's GL-free parsers, in-process so that the sanitizer build (SKINLAYER_SANITIZE,
// run by ./setup.sh test) sees every byte they read: read_angle_rows (csv_reader.h), parse_number and the formatters
// (numbers.h), ParsedFlags (flag_parser.h), material_from_flags (material_flags.h) and model_from_flags
// (model_flag.h).
//
// Inputs: random byte strings (NUL, high bytes, CR/LF, commas, very long lines), valid inputs with bytes flipped,
// inserted and deleted, random argument vectors, and a list of extreme numbers. Every generator has a fixed seed,
// so every run feeds the same inputs. Each call must either return values that keep its header's contract or throw
// exactly the documented exception with a non-empty message naming the line, flag or parameter at fault. Any other
// exception fails the test; a crash or a sanitizer report aborts it, and a hang runs into the ctest timeout.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

#include "app/cli/csv_reader.h"
#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/cli/model_flag.h"
#include "app/text/numbers.h"
#include "app/text/quoted.h"
#include "core/material.h"
#include "core/models/subsurface_model.h"

namespace skinlayer::cli {
namespace {

using Random = std::mt19937_64;

// --- Helpers ------------------------------------------------------------------------------------------------------

// A fuzz input made printable for a failure message: C escapes for control and high bytes, cut after 300 bytes.
std::string escaped(std::string_view text) {
  constexpr std::size_t kMaxShown = 300;
  std::string out = "\"";
  for (std::size_t i = 0; i < text.size() && i < kMaxShown; ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte == '\n') {
      out += "\\n";
    } else if (byte == '\r') {
      out += "\\r";
    } else if (byte == '\t') {
      out += "\\t";
    } else if (byte == '"' || byte == '\\') {
      out += '\\';
      out += static_cast<char>(byte);
    } else if (byte < 0x20 || byte >= 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", byte);
      out += hex;
    } else {
      out += static_cast<char>(byte);
    }
  }
  out += '"';
  if (text.size() > kMaxShown) out += "... (" + std::to_string(text.size()) + " bytes)";
  return out;
}

std::string escaped(const std::vector<std::string>& arguments) {
  std::string out = "[";
  for (const std::string& argument : arguments) out += escaped(argument) + " ";
  return out + "]";
}

std::size_t below(Random& random, std::size_t n) {
  return std::uniform_int_distribution<std::size_t>(0, n - 1)(random);
}

bool chance(Random& random, double p) { return std::bernoulli_distribution(p)(random); }

double uniform(Random& random, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); }

template <class T>
const T& pick(Random& random, const std::vector<T>& items) {
  return items[below(random, items.size())];
}

bool contains(std::string_view text, std::string_view part) { return text.find(part) != std::string_view::npos; }

// Stops a fuzz loop after this many failures, so that one bug does not print thousands of them.
constexpr int kMaxFailures = 10;

// Tokens at the edges of what a double and std::from_chars hold, and near misses of the number syntax.
std::vector<std::string> extreme_numbers() {
  // clang-format off
  std::vector<std::string> numbers = {
      "1e308", "1e309", "-1e309", "1.7976931348623157e308", "1.7976931348623159e308", "-1.7976931348623157e308",
      "4.9e-324", "2e-324", "1e-310", "1e-400", "-1e-400", "2.2250738585072014e-308", "0", "-0", "0.0", "-0.0",
      "nan", "NaN", "-nan", "nan(123)", "nan(", "inf", "-inf", "INF", "infinity", "infin", "0x1p3", "0X10", "1e",
      "1e+", "1e-", "1E5", ".", "-", "+1", "+0", "", " ", "  ", "\t", "1,,2", "1 2", " 1", "1 ", "1\t", "1.5.5",
      "--1", ".5", "5.", "-.5", "90", "90.000000000000001", "90.00000000000002", "89.99999999999999", "-1e-300",
      "0e999999", "1e-999999", "1e999999", "0.05", "0.049999999999999996", "2.5", "2.5000000000000004", "0.95",
      "-0.95", "0.9500000000000001", "4", "3.9999999999999996", "256", "256.00000000000006", "4.5", "1e0"};
  // clang-format on
  numbers.push_back(std::string(400, '9'));                  // 400 digits: overflows
  numbers.push_back("0." + std::string(399, '0') + "1");     // 1e-400 written out: underflows
  numbers.push_back(std::string(399, '0') + "1");            // 400 digits with leading zeros: 1
  numbers.push_back("1" + std::string(400, '0') + "e-400");  // 1 with 401 digits
  numbers.push_back("0." + std::string(400, '3'));           // 400 significant digits, in range
  numbers.push_back("-" + std::string(400, '1'));            // 400 digits, negative: overflows
  numbers.push_back(std::string(1, '\0'));                   // NUL
  numbers.push_back(std::string("1\0", 2));                  // a number, then NUL
  numbers.push_back(std::string(1, '\0') + "1");             // NUL, then a number
  numbers.push_back("\xff");
  numbers.push_back("1\xc2\xa0");  // a number and a UTF-8 no-break space
  return numbers;
}

// --- numbers.h ----------------------------------------------------------------------------------------------------

// parse_number's contract for one token; returns false after recording a failure.
bool check_number_token(const std::string& token) {
  const std::optional<double> value = text::parse_number(token);
  if (value) {
    const bool well_formed = !token.empty() && token.front() != '+' && token.find('\0') == std::string::npos &&
                             token.find_first_of(" \t\r\n") == std::string::npos;
    EXPECT_TRUE(well_formed) << "parse_number accepted " << escaped(token);
    if (!well_formed) return false;
    // The same value as strtod (which, unlike from_chars, also reads hex and leading blanks, excluded above).
    errno = 0;
    char* end = nullptr;
    const double reference = std::strtod(token.c_str(), &end);
    if (!std::isnan(*value)) {
      const bool same =
          end == token.c_str() + token.size() && reference == *value && std::signbit(reference) == std::signbit(*value);
      EXPECT_TRUE(same) << escaped(token) << ": parse_number " << text::format_number(*value) << ", strtod "
                        << text::format_number(reference);
      if (!same) return false;
    }
    // Both formatters read back as the same double.
    for (const std::string& text : {text::format_number(*value), text::format_shortest(*value)}) {
      const std::optional<double> again = text::parse_number(text);
      const bool round_trip =
          again &&
          (std::isnan(*value) ? std::isnan(*again) : *again == *value && std::signbit(*again) == std::signbit(*value));
      EXPECT_TRUE(round_trip) << escaped(token) << " -> " << escaped(text) << " does not read back";
      if (!round_trip) return false;
    }
    return true;
  }
  // Rejected: then strtod must not read it whole as an ordinary number either (no false rejection). Leading blanks,
  // '+' and hex are strtod's own extensions; ERANGE (overflow and underflow) is documented as rejected.
  if (token.empty() || token.find('\0') != std::string::npos) return true;
  const char first = token.front();
  if (first == ' ' || first == '\t' || first == '\n' || first == '\v' || first == '\f' || first == '\r' ||
      first == '+') {
    return true;
  }
  std::string lower = token;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
  if (contains(lower, "0x")) return true;
  errno = 0;
  char* end = nullptr;
  std::strtod(token.c_str(), &end);
  const bool strtod_reads_it = end == token.c_str() + token.size() && errno == 0;
  EXPECT_FALSE(strtod_reads_it) << "parse_number rejected " << escaped(token) << ", which strtod reads";
  return !strtod_reads_it;
}

TEST(ParsingFuzz, NumbersAtTheEdges) {
  const double inf = std::numeric_limits<double>::infinity();
  struct Expected {
    std::string token;
    std::optional<double> value;
  };
  const std::vector<Expected> expected = {
      {"1e308", 1e308},
      {"1e309", std::nullopt},
      {"-1e309", std::nullopt},
      {"1.7976931348623157e308", std::numeric_limits<double>::max()},
      {"4.9e-324", std::numeric_limits<double>::denorm_min()},
      {"-0", -0.0},
      {"inf", inf},
      {"-inf", -inf},
      {"infinity", inf},
      {"0x1p3", std::nullopt},
      {"1e", std::nullopt},
      {".", std::nullopt},
      {"", std::nullopt},
      {"  ", std::nullopt},
      {"1,,2", std::nullopt},
      {"+1", std::nullopt},
      {" 1", std::nullopt},
      {"1 ", std::nullopt},
      {std::string("1\0", 2), std::nullopt},
      {std::string(400, '9'), std::nullopt},
      {std::string(399, '0') + "1", 1.0},
      {"1" + std::string(400, '0') + "e-400", 1.0},
      {"0." + std::string(400, '3'), 1.0 / 3.0},
  };
  for (const Expected& e : expected) {
    const std::optional<double> value = text::parse_number(e.token);
    ASSERT_EQ(value.has_value(), e.value.has_value()) << escaped(e.token);
    if (value) {
      EXPECT_EQ(*value, *e.value) << escaped(e.token);
      EXPECT_EQ(std::signbit(*value), std::signbit(*e.value)) << escaped(e.token);
    }
  }
  for (const char* nan : {"nan", "NaN", "-nan", "nan(123)"}) {
    const std::optional<double> value = text::parse_number(nan);
    ASSERT_TRUE(value) << nan;
    EXPECT_TRUE(std::isnan(*value)) << nan;
  }
  for (const std::string& token : extreme_numbers()) check_number_token(token);
}

TEST(ParsingFuzz, RandomNumberTokensReadAsStrtodDoesOrNotAtAll) {
  Random random(0x5eed0001);
  const std::string alphabet = "0123456789.-+eEnaifNAIFx( )";
  const std::vector<std::string> extremes = extreme_numbers();
  int failures = 0;
  for (int trial = 0; trial < 20000 && failures < kMaxFailures; ++trial) {
    std::string token;
    if (chance(random, 0.3)) token = pick(random, extremes);
    const std::size_t length = below(random, 12);
    for (std::size_t i = 0; i < length; ++i) {
      token += chance(random, 0.9) ? alphabet[below(random, alphabet.size())] : static_cast<char>(below(random, 256));
    }
    if (chance(random, 0.3)) {  // a random finite double in one of its written forms
      const double value = std::ldexp(uniform(random, -1.0, 1.0), static_cast<int>(below(random, 2100)) - 1075);
      token = chance(random, 0.5) ? text::format_number(value) : text::format_shortest(value);
    }
    if (!check_number_token(token)) ++failures;
  }
}

// --- csv_reader.h -------------------------------------------------------------------------------------------------

constexpr std::string_view kHeader = "theta_i,theta_o,phi";
constexpr std::string_view kNoDataRows = "no data rows";

// The lines std::getline gives: split at '\n'; a final '\n' does not start another line.
std::vector<std::string_view> lines_of(std::string_view text) {
  std::vector<std::string_view> lines;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    lines.push_back(text.substr(0, end));
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return lines;
}

// The text up to the end of line `count` (1-based), its line end included.
std::string first_lines(std::string_view text, std::size_t count) {
  std::size_t end = 0;
  for (std::size_t line = 0; line < count; ++line) {
    const std::size_t newline = text.find('\n', end);
    if (newline == std::string_view::npos) return std::string(text);
    end = newline + 1;
  }
  return std::string(text.substr(0, end));
}

std::string without_blanks(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c != ' ' && c != '\t') out += c;
  }
  return out;
}

std::string_view without_cr(std::string_view line) {
  if (line.ends_with('\r')) line.remove_suffix(1);
  return line;
}

std::string_view trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// The outcome of reading text: the rows, or the InputError's message. Any other exception is a failure.
struct CsvOutcome {
  std::optional<std::vector<AngleRow>> rows;
  std::string error;
  bool unexpected = false;
};

CsvOutcome read_csv(const std::string& text) {
  std::istringstream in(text);
  CsvOutcome outcome;
  try {
    outcome.rows = read_angle_rows(in);
  } catch (const InputError& error) {
    outcome.error = error.what();
  } catch (const std::exception& error) {
    ADD_FAILURE() << "read_angle_rows threw " << typeid(error).name() << " (" << error.what() << ") for "
                  << escaped(text);
    outcome.unexpected = true;
  } catch (...) {
    ADD_FAILURE() << "read_angle_rows threw a non-std exception for " << escaped(text);
    outcome.unexpected = true;
  }
  return outcome;
}

enum class CsvCheck { Read, Rejected, Failed };

// read_angle_rows's contract for one input: rows, or an InputError as documented (else a failure is recorded).
CsvCheck check_csv(const std::string& text) {
  const CsvOutcome outcome = read_csv(text);
  if (outcome.unexpected) return CsvCheck::Failed;
  const std::vector<std::string_view> lines = lines_of(text);
  if (outcome.rows) {
    const std::vector<AngleRow>& rows = *outcome.rows;
    // One row per line, after an optional header; every value is the number its field holds, in range.
    const bool header =
        !rows.empty() && rows.size() + 1 == lines.size() && without_blanks(without_cr(lines.front())) == kHeader;
    const bool counted = !rows.empty() && (rows.size() == lines.size() || header);
    EXPECT_TRUE(counted) << rows.size() << " rows from " << lines.size() << " lines of " << escaped(text);
    if (!counted) return CsvCheck::Failed;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const AngleRow& row = rows[r];
      const bool in_range = row.theta_i >= 0.0 && row.theta_i <= 90.0 && row.theta_o >= 0.0 && row.theta_o <= 90.0 &&
                            std::isfinite(row.phi);
      EXPECT_TRUE(in_range) << "row " << r << " (" << row.theta_i << ", " << row.theta_o << ", " << row.phi
                            << ") out of range from " << escaped(text);
      if (!in_range) return CsvCheck::Failed;
      std::string_view line = without_cr(lines[r + (header ? 1 : 0)]);
      const double values[] = {row.theta_i, row.theta_o, row.phi};
      for (const double value : values) {
        const std::size_t comma = line.find(',');
        const std::optional<double> field = text::parse_number(trimmed(line.substr(0, comma)));
        const bool same = field && *field == value && std::signbit(*field) == std::signbit(value);
        EXPECT_TRUE(same) << "row " << r << " is not its line's numbers in " << escaped(text);
        if (!same) return CsvCheck::Failed;
        line.remove_prefix(comma == std::string_view::npos ? line.size() : comma + 1);
      }
    }
    return CsvCheck::Read;
  }
  // An InputError: "line N: ..." for an existing line N, or no data rows at all (empty input or a header alone).
  const std::string& message = outcome.error;
  if (message.starts_with(kNoDataRows)) {
    const bool no_rows = lines.empty() || (lines.size() == 1 && without_blanks(without_cr(lines[0])) == kHeader);
    EXPECT_TRUE(no_rows) << "\"" << message << "\" for " << lines.size() << " lines " << escaped(text);
    return no_rows ? CsvCheck::Rejected : CsvCheck::Failed;
  }
  unsigned long line_number = 0;
  int consumed = 0;
  const bool names_line = std::sscanf(message.c_str(), "line %lu: %n", &line_number, &consumed) == 1 && consumed > 0 &&
                          static_cast<std::size_t>(consumed) < message.size() && line_number >= 1 &&
                          line_number <= lines.size();
  EXPECT_TRUE(names_line) << "InputError \"" << escaped(message) << "\" names no line of the " << lines.size() << " in "
                          << escaped(text);
  if (!names_line) return CsvCheck::Failed;
  // Rows are read in order: the first N lines fail alike, and the N - 1 before them have no malformed line.
  const CsvOutcome up_to = read_csv(first_lines(text, line_number));
  const bool same_error = !up_to.unexpected && !up_to.rows && up_to.error == message;
  EXPECT_TRUE(same_error) << "the first " << line_number << " lines of " << escaped(text) << " give \""
                          << escaped(up_to.error) << "\", not \"" << escaped(message) << "\"";
  if (!same_error) return CsvCheck::Failed;
  const CsvOutcome before = read_csv(first_lines(text, line_number - 1));
  const bool before_ok = !before.unexpected && (before.rows || before.error.starts_with(kNoDataRows));
  EXPECT_TRUE(before_ok) << "the " << line_number - 1 << " lines before the one named by \"" << escaped(message)
                         << "\" fail too: \"" << escaped(before.error) << "\"";
  return before_ok ? CsvCheck::Rejected : CsvCheck::Failed;
}

// A valid table: optional header, 1 to 6 rows written in assorted forms, LF or CRLF, optional final line end.
std::string valid_csv(Random& random, std::vector<AngleRow>* rows_out) {
  const std::string line_end = chance(random, 0.3) ? "\r\n" : "\n";
  auto blanks = [&random]() -> std::string {
    if (!chance(random, 0.2)) return "";
    return pick(random, std::vector<std::string>{" ", "\t", "  ", " \t "});
  };
  auto written = [&random](double value) -> std::string {
    switch (below(random, 3)) {
      case 0:
        return text::format_shortest(value);
      case 1:
        return text::format_number(value);
      default: {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.3e", value);
        return buffer;
      }
    }
  };
  auto polar = [&random]() {
    switch (below(random, 6)) {
      case 0:
        return 0.0;
      case 1:
        return 90.0;
      case 2:
        return -0.0;
      default:
        return uniform(random, 0.0, 90.0);
    }
  };
  auto azimuth = [&random]() {
    switch (below(random, 6)) {
      case 0:
        return 1e308;
      case 1:
        return -360.0;
      case 2:
        return 4.9e-324;
      default:
        return uniform(random, -1e4, 1e4);
    }
  };
  std::string text;
  if (chance(random, 0.5)) text += blanks() + "theta_i" + blanks() + ",theta_o," + blanks() + "phi" + line_end;
  const std::size_t count = 1 + below(random, 6);
  std::vector<AngleRow> rows;
  for (std::size_t r = 0; r < count; ++r) {
    std::string values[3];
    double numbers[3] = {polar(), polar(), azimuth()};
    for (int c = 0; c < 3; ++c) {
      values[c] = written(numbers[c]);
      numbers[c] = *text::parse_number(values[c]);  // the value as written (%.3e rounds)
    }
    // Rounding to %.3e cannot leave [0, 90]: 0 and 90 are exact, and the rest rounds within.
    rows.push_back({numbers[0], numbers[1], numbers[2]});
    text += blanks() + values[0] + blanks() + "," + blanks() + values[1] + "," + values[2] + blanks();
    if (r + 1 < count || chance(random, 0.7)) text += line_end;
  }
  if (rows_out) *rows_out = rows;
  return text;
}

// 1 to 4 random edits: bits flipped, bytes replaced, inserted (often a separator or a NUL) or deleted, ranges
// deleted or repeated.
void mutate(Random& random, std::string& text) {
  const std::string specials = std::string(",\n\r\t .-e+") + std::string(1, '\0') + "\xffni";
  const std::size_t edits = chance(random, 0.5) ? 1 : 1 + below(random, 4);
  for (std::size_t e = 0; e < edits; ++e) {
    const std::size_t at = text.empty() ? 0 : below(random, text.size());
    switch (below(random, 6)) {
      case 0:
        if (!text.empty()) text[at] = static_cast<char>(text[at] ^ (1 << below(random, 8)));
        break;
      case 1:
        if (!text.empty()) text[at] = static_cast<char>(below(random, 256));
        break;
      case 2:
        text.insert(at, 1, specials[below(random, specials.size())]);
        break;
      case 3:
        text.insert(at, 1, static_cast<char>(below(random, 256)));
        break;
      case 4:
        if (!text.empty()) text.erase(at, 1 + below(random, 4));
        break;
      default:
        if (!text.empty()) text.insert(at, text.substr(at, 1 + below(random, 8)));
        break;
    }
  }
}

TEST(ParsingFuzz, CsvValidTablesReadExactly) {
  Random random(0x5eed0002);
  int failures = 0;
  for (int trial = 0; trial < 2000 && failures < kMaxFailures; ++trial) {
    std::vector<AngleRow> expected;
    const std::string text = valid_csv(random, &expected);
    const CsvOutcome outcome = read_csv(text);
    const bool ok =
        outcome.rows && outcome.rows->size() == expected.size() &&
        std::equal(expected.begin(), expected.end(), outcome.rows->begin(), [](const AngleRow& a, const AngleRow& b) {
          return a.theta_i == b.theta_i && a.theta_o == b.theta_o && a.phi == b.phi;
        });
    EXPECT_TRUE(ok) << escaped(text) << ": " << outcome.error;
    if (!ok || check_csv(text) == CsvCheck::Failed) ++failures;
  }
}

TEST(ParsingFuzz, CsvMutatedTablesReadOrFailNamingTheLine) {
  Random random(0x5eed0003);
  int failures = 0, read = 0, rejected = 0;
  for (int trial = 0; trial < 6000 && failures < kMaxFailures; ++trial) {
    std::string text = valid_csv(random, nullptr);
    mutate(random, text);
    const CsvCheck check = check_csv(text);
    failures += check == CsvCheck::Failed;
    read += check == CsvCheck::Read;
    rejected += check == CsvCheck::Rejected;
  }
  // Both outcomes are exercised: many edits keep a table valid (a digit for a digit), many break it.
  EXPECT_GT(read, 600);
  EXPECT_GT(rejected, 600);
}

TEST(ParsingFuzz, CsvRandomBytesReadOrFailNamingTheLine) {
  Random random(0x5eed0004);
  const std::vector<std::string> extremes = extreme_numbers();
  const std::vector<std::string> pieces = {
      ",",  "\n", "\r\n", "\r",  " ",      "\t", std::string(1, '\0'), std::string(kHeader),
      "30", "90", "-1",   "1e1", "theta_i"};
  int failures = 0, read = 0;
  for (int trial = 0; trial < 6000 && failures < kMaxFailures; ++trial) {
    std::string text;
    if (chance(random, 0.3)) {  // rows of three random fields
      const std::size_t rows = 1 + below(random, 4);
      for (std::size_t r = 0; r < rows; ++r) {
        for (int field = 0; field < 3; ++field) {
          if (field > 0) text += chance(random, 0.95) ? "," : pick(random, pieces);
          text += chance(random, 0.5) ? pick(random, extremes) : std::to_string(below(random, 100));
        }
        text += chance(random, 0.5) ? "\n" : pick(random, pieces);
      }
    } else {
      const std::size_t parts = below(random, 24);
      for (std::size_t p = 0; p < parts; ++p) {
        switch (below(random, 4)) {
          case 0:
            text += static_cast<char>(below(random, 256));
            break;
          case 1:
            text += pick(random, pieces);
            break;
          case 2:
            text += pick(random, extremes);
            break;
          default:
            text += "0123456789.-e,"[below(random, 14)];
            break;
        }
      }
    }
    const CsvCheck check = check_csv(text);
    failures += check == CsvCheck::Failed;
    read += check == CsvCheck::Read;
  }
  EXPECT_GT(read, 50);
}

// Every extreme number in every column of an otherwise valid row: read exactly when it is a number in the column's
// range, else an InputError naming line 2 and the column.
TEST(ParsingFuzz, CsvExtremeNumbersInEveryColumn) {
  const char* const columns[] = {"theta_i", "theta_o", "phi"};
  for (const std::string& token : extreme_numbers()) {
    for (int column = 0; column < 3; ++column) {
      std::string fields[3] = {"30", "45", "180"};
      fields[column] = token;
      const std::string text = "theta_i,theta_o,phi\n" + fields[0] + "," + fields[1] + "," + fields[2] + "\n";
      const std::optional<double> value = text::parse_number(trimmed(token));
      // A token holding a comma, or a line end, is not one field; check_csv covers it.
      const bool one_field = token.find_first_of(",\n") == std::string::npos;
      const bool valid = one_field && value && (column == 2 ? std::isfinite(*value) : *value >= 0.0 && *value <= 90.0);
      const CsvOutcome outcome = read_csv(text);
      EXPECT_NE(check_csv(text), CsvCheck::Failed);
      if (!one_field) continue;
      if (valid) {
        ASSERT_TRUE(outcome.rows) << escaped(text) << ": " << outcome.error;
        const double read[] = {outcome.rows->front().theta_i, outcome.rows->front().theta_o, outcome.rows->front().phi};
        EXPECT_EQ(read[column], *value) << escaped(text);
      } else {
        EXPECT_TRUE(outcome.error.starts_with(std::string("line 2: ") + columns[column] + " = "))
            << escaped(text) << ": \"" << escaped(outcome.error) << "\"";
      }
    }
  }
}

TEST(ParsingFuzz, CsvVeryLongLines) {
  const std::size_t kLong = 200000;
  const std::vector<std::string> inputs = {
      "1" + std::string(kLong, '0') + ",0,0\n",                               // a 200001-digit theta_i: overflows
      "0." + std::string(kLong, '0') + "1,0,0\n",                             // underflows
      "0." + std::string(kLong, '3') + ",0,0\n",                              // in range, 200000 digits
      "30,30," + std::string(kLong, '9') + "\n",                              // phi overflows
      std::string(kLong, ',') + "\n",                                         // 200001 empty fields
      std::string(kLong, ' ') + "30" + std::string(kLong, '\t') + ",30,0\n",  // blanks around a field
      std::string(kLong, ' ') + "\n30,30,0\n",                                // a long blank line
      "30,30,0\n" + std::string(kLong, '\0') + "\n",                          // a line of NULs
      std::string(kLong, '\n'),                                               // many blank lines
      "theta_i,theta_o,phi" + std::string(kLong, '\r') + "\n30,30,0\n",
  };
  for (const std::string& text : inputs) {
    EXPECT_NE(check_csv(text), CsvCheck::Failed) << escaped(text);
    const CsvOutcome outcome = read_csv(text);
    EXPECT_LT(outcome.error.size(), 400u) << "message not cut: " << escaped(outcome.error);
  }
  // Many rows.
  std::string many = std::string(kHeader) + "\n";
  for (int r = 0; r < 20000; ++r) many += std::to_string(r % 91) + "," + std::to_string((r * 7) % 91) + ",180\n";
  const CsvOutcome outcome = read_csv(many);
  ASSERT_TRUE(outcome.rows) << outcome.error;
  EXPECT_EQ(outcome.rows->size(), 20000u);
  // 1 MB of random bytes on one line.
  Random random(0x5eed0005);
  std::string noise(1 << 20, '\0');
  for (char& c : noise) {
    c = static_cast<char>(below(random, 256));
    if (c == '\n') c = ',';
  }
  EXPECT_NE(check_csv(noise), CsvCheck::Failed);
}

// --- flag_parser.h ------------------------------------------------------------------------------------------------

// What flag_parser.h documents for an argument vector: the (name, value) pairs, or the text that the UsageError
// must contain (the argument or flag at fault).
struct ExpectedFlags {
  std::vector<std::pair<std::string, std::string>> values;
  std::optional<std::string> error_names;
};

ExpectedFlags expected_flags(const std::vector<std::string>& arguments, const std::vector<std::string_view>& known,
                             const std::vector<std::string_view>& switches) {
  const auto is_known = [&known](std::string_view name) {
    return std::find(known.begin(), known.end(), name) != known.end();
  };
  const auto is_switch = [&switches](std::string_view name) {
    return std::find(switches.begin(), switches.end(), name) != switches.end();
  };
  ExpectedFlags expected;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& argument = arguments[i];
    std::string body;
    if (argument == "-o" && is_known("output")) {
      body = "output";
    } else if (argument.starts_with("--") && argument.size() > 2) {
      body = argument.substr(2);
    } else {
      expected.error_names = text::quoted(argument);  // not a flag
      return expected;
    }
    const std::size_t equals = body.find('=');
    const std::string name = body.substr(0, equals);
    if (!is_known(name) && !is_switch(name)) {
      expected.error_names = text::quoted("--" + name);
      return expected;
    }
    std::string value;
    if (is_switch(name)) {
      if (equals != std::string::npos) {
        expected.error_names = "--" + name;  // a switch given a value
        return expected;
      }
    } else if (equals != std::string::npos) {
      value = body.substr(equals + 1);
    } else if (i + 1 < arguments.size() && !arguments[i + 1].starts_with("--")) {
      value = arguments[++i];
    } else {
      expected.error_names = "--" + name;  // no value
      return expected;
    }
    const bool repeatable =
        std::find(std::begin(kRepeatableFlags), std::end(kRepeatableFlags), name) != std::end(kRepeatableFlags);
    for (const auto& [given, unused] : expected.values) {
      if (given == name && !repeatable) {
        expected.error_names = "--" + name;  // twice
        return expected;
      }
    }
    expected.values.emplace_back(name, value);
  }
  return expected;
}

std::string random_bytes(Random& random, std::size_t max_length) {
  std::string text(below(random, max_length + 1), '\0');
  for (char& c : text) c = static_cast<char>(below(random, 256));
  return text;
}

// Parses arguments against known flags and switches, checks the outcome against expected_flags, and returns the
// flags when parsed.
std::optional<ParsedFlags> check_parse(const std::vector<std::string>& arguments,
                                       const std::vector<std::string_view>& known,
                                       const std::vector<std::string_view>& switches, bool& failed) {
  const std::vector<std::string_view> views(arguments.begin(), arguments.end());
  const ExpectedFlags expected = expected_flags(arguments, known, switches);
  const bool help =
      std::any_of(arguments.begin(), arguments.end(), [](const std::string& a) { return a == "--help" || a == "-h"; });
  if (wants_help(views) != help) {
    ADD_FAILURE() << "wants_help is " << !help << " for " << escaped(arguments);
    failed = true;
  }
  try {
    ParsedFlags flags = ParsedFlags::parse(views, known, "skinlayer fuzz", switches);
    if (expected.error_names) {
      ADD_FAILURE() << "parsed, but expected a UsageError naming " << escaped(*expected.error_names) << ": "
                    << escaped(arguments);
      failed = true;
      return std::nullopt;
    }
    std::vector<std::string_view> names = known;
    names.insert(names.end(), switches.begin(), switches.end());
    for (const std::string_view name : names) {
      std::optional<std::string> want;  // the first value given (value() of a repeatable flag)
      std::vector<std::string_view> all;
      for (const auto& [given, value] : expected.values) {
        if (given != name) continue;
        if (!want) want = value;
        all.push_back(value);
      }
      if (flags.values(name) != all) {
        ADD_FAILURE() << "flag " << name << ": values() differ from " << escaped(arguments);
        failed = true;
      }
      const std::optional<std::string_view> got = flags.value(name);
      if (got.has_value() != want.has_value() || (got && *got != *want) || flags.has(name) != want.has_value()) {
        ADD_FAILURE() << "flag " << name << ": got " << (got ? escaped(*got) : "none") << ", want "
                      << (want ? escaped(*want) : "none") << " from " << escaped(arguments);
        failed = true;
      }
    }
    return flags;
  } catch (const UsageError& error) {
    const std::string message = error.what();
    if (!expected.error_names) {
      ADD_FAILURE() << "UsageError \"" << escaped(message) << "\" for valid " << escaped(arguments);
      failed = true;
    } else if (!contains(message, *expected.error_names)) {
      ADD_FAILURE() << "UsageError \"" << escaped(message) << "\" does not name " << escaped(*expected.error_names)
                    << " for " << escaped(arguments);
      failed = true;
    }
  } catch (const std::exception& error) {
    ADD_FAILURE() << "ParsedFlags::parse threw " << typeid(error).name() << " (" << error.what() << ") for "
                  << escaped(arguments);
    failed = true;
  } catch (...) {
    ADD_FAILURE() << "ParsedFlags::parse threw a non-std exception for " << escaped(arguments);
    failed = true;
  }
  return std::nullopt;
}

TEST(ParsingFuzz, FlagParserRandomArguments) {
  Random random(0x5eed0006);
  const std::vector<std::string_view> with_output = {"alpha", "beta", "output", "g", "bottom-sigma"};
  const std::vector<std::string_view> without_output = {"alpha", "beta", "g"};
  const std::vector<std::string_view> switches = {"quick", "verbose"};
  const std::vector<std::string> tokens = {"--alpha",
                                           "--beta",
                                           "--output",
                                           "--g",
                                           "--bottom-sigma",
                                           "-o",
                                           "--alpha=",
                                           "--alpha=1",
                                           "--alpha==",
                                           "--quick",
                                           "--quick",
                                           "--verbose",
                                           "--quick=",
                                           "--quick=1",
                                           "--verbose=--quick",
                                           "--beta=--alpha",
                                           "--",
                                           "---",
                                           "--=",
                                           "--=1",
                                           "-h",
                                           "--help",
                                           "-",
                                           "",
                                           "value",
                                           "1",
                                           "-1",
                                           "--unknown",
                                           "--Alpha",
                                           "--alpha ",
                                           std::string("--alpha\0x", 9),
                                           "-o=x",
                                           "--o",
                                           "--output=-o",
                                           "--g=\xff",
                                           std::string("--g\0", 4)};
  int failures = 0;
  for (int trial = 0; trial < 20000 && failures < kMaxFailures; ++trial) {
    std::vector<std::string> arguments(below(random, 9));
    for (std::string& argument : arguments) {
      switch (below(random, 5)) {
        case 0:
          argument = random_bytes(random, 12);
          break;
        case 1:
          argument = "--" + random_bytes(random, 8);
          break;
        default:
          argument = pick(random, tokens);
          break;
      }
    }
    bool failed = false;
    check_parse(arguments, chance(random, 0.7) ? with_output : without_output,
                chance(random, 0.5) ? switches : std::vector<std::string_view>{}, failed);
    if (failed) ++failures;
  }
}

// --- material_flags.h and model_flag.h ----------------------------------------------------------------------------

constexpr std::string_view kNumericFlags[] = {"sigma", "eta", "T", "tau", "albedo", "g", "bottom-sigma", "bottom-eta"};

// A value for the flag: mostly one its contract accepts, else an edge or junk.
std::string random_value(Random& random, std::string_view flag, const std::vector<std::string>& extremes) {
  if (chance(random, 0.15)) return pick(random, extremes);
  if (chance(random, 0.05)) return random_bytes(random, 10);
  if (flag == "bottom") {
    static const std::vector<std::string> bottoms = {"air",         "matched",        "lambert:0",
                                                     "lambert:1",   "lambert:0.5",    "lambert:",
                                                     "lambert:nan", "lambert:-0",     "lambert:1e309",
                                                     "lambert:+1",  "lambert: 1",     "lambert:1.5",
                                                     "Lambert:1",   "air ",           "",
                                                     "lambert:0x1", "lambert:1e-400", std::string("matched\0", 8)};
    return pick(random, bottoms);
  }
  if (flag == "model") {
    static const std::vector<std::string> models = {"stam", "lambert", "hk", "Stam", "", "hk ", "lambert:1"};
    return pick(random, models);
  }
  if (flag == "ordinates") {
    static const std::vector<std::string> ordinates = {"4",   "256", "16", "3",          "257", "4.5",
                                                       "8.0", "1e2", "-4", "2147483648", "nan", "inf"};
    return pick(random, ordinates);
  }
  if (std::find(std::begin(kNumericFlags), std::end(kNumericFlags), flag) == std::end(kNumericFlags)) {
    return chance(random, 0.5) ? pick(random, extremes) : random_bytes(random, 10);
  }
  const ParameterInfo& info = parameter_info(flag);
  const double hi = std::isfinite(info.max) ? info.max : 50.0;
  double value = 0.0;
  switch (below(random, 5)) {
    case 0:
      value = info.min;
      break;
    case 1:
      value = info.max;
      break;
    case 2:
      value = std::nextafter(chance(random, 0.5) ? info.min : hi, chance(random, 0.5) ? -1e9 : 1e9);
      break;
    default:
      value = uniform(random, info.min, hi);
      break;
  }
  return chance(random, 0.5) ? text::format_shortest(value) : text::format_number(value);
}

enum class MaterialOutcome { Built, Rejected, Failed };

// material_from_flags's contract for parsed flags: a valid Material whose every field is its flag's value (or the
// default), or a ParameterError / UsageError naming a flag that was given.
MaterialOutcome check_material(const ParsedFlags& flags, const std::vector<std::string>& arguments) {
  std::vector<std::string> given;
  for (const std::string_view name : material_flag_names()) {
    if (flags.has(name)) given.emplace_back(name);
  }
  const auto names_given_flag = [&given](const std::string& message) {
    for (const std::string& name : given) {
      if (message.starts_with(name + " = ") || contains(message, "--" + name)) return true;
      if (name == "bottom" && message.starts_with("lambert = ")) return true;  // core's name for A of lambert:A
    }
    return false;
  };
  const auto number = [&flags](std::string_view name) { return *text::parse_number(*flags.value(name)); };
  std::optional<Material> built;
  try {
    built = material_from_flags(flags);
  } catch (const ParameterError& error) {
    // Out of range or NaN: the flag's text is a number (or the bottom's spelling is wrong).
    const std::string message = error.what();
    bool ok = !message.empty() && names_given_flag(message);
    for (const std::string_view name : kNumericFlags) {
      if (flags.has(name) && message.starts_with(std::string(name) + " = ") &&
          !text::parse_number(*flags.value(name))) {
        ok = false;  // a non-number must be a UsageError
      }
    }
    EXPECT_TRUE(ok) << "ParameterError \"" << escaped(message) << "\" for " << escaped(arguments);
    return ok ? MaterialOutcome::Rejected : MaterialOutcome::Failed;
  } catch (const UsageError& error) {
    const std::string message = error.what();
    bool ok = !message.empty() && names_given_flag(message);
    for (const std::string_view name : kNumericFlags) {
      if (flags.has(name) && message.starts_with(std::string(name) + " = ") && contains(message, "is not a number") &&
          text::parse_number(*flags.value(name))) {
        ok = false;  // a number out of range must be a ParameterError
      }
    }
    EXPECT_TRUE(ok) << "UsageError \"" << escaped(message) << "\" for " << escaped(arguments);
    return ok ? MaterialOutcome::Rejected : MaterialOutcome::Failed;
  } catch (const std::exception& error) {
    ADD_FAILURE() << "material_from_flags threw " << typeid(error).name() << " (" << error.what() << ") for "
                  << escaped(arguments);
    return MaterialOutcome::Failed;
  } catch (...) {
    ADD_FAILURE() << "material_from_flags threw a non-std exception for " << escaped(arguments);
    return MaterialOutcome::Failed;
  }
  const Material& m = *built;
  try {
    validate(m);
  } catch (const std::exception& error) {
    ADD_FAILURE() << "material_from_flags returned a material that validate rejects (" << error.what() << ") for "
                  << escaped(arguments);
    return MaterialOutcome::Failed;
  }
  const Material defaults;
  bool ok = true;
  const auto expect_field = [&](std::string_view name, double field, double default_value) {
    const double want = flags.has(name) ? number(name) : default_value;
    if (field != want) {
      ADD_FAILURE() << name << " = " << field << ", want " << want << " from " << escaped(arguments);
      ok = false;
    }
  };
  expect_field("sigma", m.sigma, defaults.sigma);
  expect_field("eta", m.eta, defaults.eta);
  expect_field("albedo", m.albedo, defaults.albedo);
  expect_field("g", m.g, defaults.g);
  if (flags.has("T")) {
    expect_field("tau", m.tau, optical_depth_from_transparency(number("T")));
  } else {
    expect_field("tau", m.tau, defaults.tau);
  }
  const std::string bottom(flags.value("bottom").value_or("air"));
  const BottomKind kind = bottom == "air"       ? BottomKind::Air
                          : bottom == "matched" ? BottomKind::Matched
                                                : BottomKind::Lambert;
  const bool bottom_ok =
      m.bottom.kind == kind && (kind != BottomKind::Lambert ||
                                (bottom.starts_with("lambert:") &&
                                 m.bottom.lambert_albedo == *text::parse_number(std::string_view(bottom).substr(8))));
  const bool bottom_optionals_ok = m.bottom.sigma.has_value() == flags.has("bottom-sigma") &&
                                   m.bottom.eta.has_value() == flags.has("bottom-eta") &&
                                   (!m.bottom.sigma || *m.bottom.sigma == number("bottom-sigma")) &&
                                   (!m.bottom.eta || *m.bottom.eta == number("bottom-eta"));
  const bool ordinates_ok = m.ordinates.has_value() == flags.has("ordinates") &&
                            (!m.ordinates || *m.ordinates == static_cast<int>(number("ordinates")));
  if (!bottom_ok || !bottom_optionals_ok || !ordinates_ok) {
    ADD_FAILURE() << "bottom " << format_bottom(m.bottom) << " / ordinates " << m.ordinates.value_or(0)
                  << " do not match " << escaped(arguments);
    ok = false;
  }
  return ok ? MaterialOutcome::Built : MaterialOutcome::Failed;
}

// model_from_flags's contract: stam by default, the named model, or a UsageError naming --model's value.
bool check_model(const ParsedFlags& flags, const std::vector<std::string>& arguments) {
  const std::optional<std::string_view> text = flags.value(kModelFlag);
  const std::optional<SubsurfaceModel> want =
      text ? parse_subsurface_model(*text) : std::optional<SubsurfaceModel>(SubsurfaceModel::Stam);
  try {
    const SubsurfaceModel model = model_from_flags(flags);
    EXPECT_TRUE(want && model == *want) << "model " << subsurface_model_name(model) << " from " << escaped(arguments);
    return want && model == *want;
  } catch (const UsageError& error) {
    const std::string message = error.what();
    const bool ok = !want && message.starts_with("model = ") && contains(message, text::quoted(*text));
    EXPECT_TRUE(ok) << "UsageError \"" << escaped(message) << "\" for " << escaped(arguments);
    return ok;
  } catch (const std::exception& error) {
    ADD_FAILURE() << "model_from_flags threw " << typeid(error).name() << " (" << error.what() << ") for "
                  << escaped(arguments);
  } catch (...) {
    ADD_FAILURE() << "model_from_flags threw a non-std exception for " << escaped(arguments);
  }
  return false;
}

TEST(ParsingFuzz, MaterialAndModelFlagsRandomArguments) {
  Random random(0x5eed0007);
  const std::vector<std::string> extremes = extreme_numbers();
  // The parameter flags and --model; --material and --preset read files and presets, fuzzed by
  // MaterialJsonRandomDocuments below, and --layer has its own (LayerSpecsRandomArguments).
  std::vector<std::string_view> known;
  for (const std::string_view name : material_flag_names()) {
    if (name != "layer") known.push_back(name);
  }
  known.push_back(kModelFlag);
  std::vector<std::string> names(known.begin(), known.end());
  names.insert(names.end(), {"sigmaa", "Sigma", "", "output", "help"});
  int failures = 0, materials = 0;
  for (int trial = 0; trial < 20000 && failures < kMaxFailures; ++trial) {
    std::vector<std::string> arguments;
    const std::size_t count = below(random, 8);
    for (std::size_t f = 0; f < count; ++f) {
      const std::string& name = chance(random, 0.9) ? names[below(random, known.size())] : pick(random, names);
      const std::string value = random_value(random, name, extremes);
      switch (below(random, 20)) {
        case 0:
          arguments.push_back("--" + name);
          break;  // no value
        case 1:
          arguments.push_back(random_bytes(random, 6));
          break;  // junk
        case 2:
        case 3:
        case 4:
        case 5:
        case 6:
          arguments.push_back("--" + name + "=" + value);
          break;
        default:
          arguments.push_back("--" + name);
          arguments.push_back(value);
          break;
      }
    }
    bool failed = false;
    const std::optional<ParsedFlags> flags = check_parse(arguments, known, {}, failed);
    if (flags) {
      const MaterialOutcome outcome = check_material(*flags, arguments);
      failed |= outcome == MaterialOutcome::Failed;
      failed |= !check_model(*flags, arguments);
      if (outcome == MaterialOutcome::Built) ++materials;
    }
    if (failed) ++failures;
  }
  // Enough argument vectors got through to a material for its fields to have been checked.
  EXPECT_GT(materials, 1000);
}

// --layer specs (app/cli/layer_flag.h): random stacks of random specs against an oracle written from the contract.
// A stack either builds, with every layer's fields as its spec says (defaults where a key is absent), or is refused
// with one message that starts with the place of the first faulty layer ("layer 2: ").
TEST(ParsingFuzz, LayerSpecsRandomArguments) {
  Random random(0x5eed0011);
  const std::vector<std::string> keys = {"T", "tau", "albedo", "g", "sigma", "eta", "t", "omega", ""};
  const std::vector<std::string> numbers = {"0",   "1",   "0.5", "0.2",         "0.95",  "-0.95", "2.5",
                                            "0.4", "inf", "nan", "1e309",       "-0",    "0.05",  "3",
                                            "x",   "",    "1.2", "0.9:0.8:0.7", "1e-400"};
  const std::vector<std::string_view> known = {"layer", "sigma", "eta", "bottom"};
  int built = 0, refused = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const std::size_t count = 1 + below(random, 4);
    std::vector<std::vector<std::pair<std::string, std::string>>> specs(count);
    std::vector<std::string> arguments;
    for (auto& spec : specs) {
      // Mostly well-formed: a depth key, then a few others.
      if (chance(random, 0.9)) spec.emplace_back(chance(random, 0.5) ? "T" : "tau", pick(random, numbers));
      const std::size_t extra = below(random, 4);
      for (std::size_t k = 0; k < extra; ++k) spec.emplace_back(pick(random, keys), pick(random, numbers));
      std::string text;
      for (const auto& [key, value] : spec) text += (text.empty() ? "" : ",") + key + "=" + value;
      arguments.push_back("--layer");
      arguments.push_back(text.empty() ? "T=0.5" : text);
      if (text.empty()) spec = {{"T", "0.5"}};
    }
    const std::vector<std::string_view> views(arguments.begin(), arguments.end());
    // --layer values never start with "--", so parsing always succeeds.
    const ParsedFlags flags = ParsedFlags::parse(views, known, "skinlayer fuzz");

    // The oracle: the first faulty layer, or the expected layers.
    std::optional<std::size_t> faulty;
    std::vector<StackedLayer> expected;
    for (std::size_t i = 0; i < count && !faulty; ++i) {
      const auto& spec = specs[i];
      std::map<std::string, std::string> values;
      bool bad = false;
      for (const auto& [key, value] : spec) {
        const bool valid_key =
            key == "T" || key == "tau" || key == "albedo" || key == "g" || key == "sigma" || key == "eta";
        bad |= !valid_key || values.count(key) > 0;
        values[key] = value;
      }
      bad |= values.count("T") == values.count("tau");  // exactly one
      bad |= (values.count("sigma") != values.count("eta")) || (i == 0 && values.count("sigma") > 0);
      const auto in_range = [&](const std::string& key, const ParameterInfo& info, double& out) {
        if (!values.count(key)) return;
        const std::optional<double> v = text::parse_number(values[key]);
        if (!v || !(*v >= info.min && *v <= info.max)) {
          bad = true;
          return;
        }
        out = *v;
      };
      StackedLayer layer{0.0, parameter_info("albedo").default_value, parameter_info("g").default_value, {}};
      double t = 0.0;
      in_range("T", parameter_info("T"), t);
      if (values.count("T") && !bad) layer.tau = optical_depth_from_transparency(t);
      in_range("tau", parameter_info("tau"), layer.tau);
      in_range("albedo", parameter_info("albedo"), layer.albedo);
      in_range("g", parameter_info("g"), layer.g);
      if (values.count("sigma")) {
        LayerInterface interface;
        in_range("sigma", parameter_info("sigma"), interface.sigma);
        in_range("eta", interface_eta_info(), interface.eta);
        layer.interface = interface;
      }
      if (bad) faulty = i;
      expected.push_back(layer);
    }
    if (!faulty) {
      for (std::size_t i = 0; i + 1 < count; ++i) {
        if (std::isinf(expected[i].tau)) {
          faulty = i;
          break;
        }
      }
    }
    // Air below the last layer (the default bottom): n_last / n_air = 1.4 (the default top) times the interfaces'
    // eta must be a valid bottom-eta.
    double index = Material{}.eta;  // (expected holds every layer only when none is faulty)
    for (std::size_t i = 1; i < expected.size(); ++i) {
      index *= expected[i].interface ? expected[i].interface->eta : 1.0;
    }
    const bool bad_bottom = !faulty && count > 1 && !(index >= 1.0 && index <= 2.5);
    try {
      const Material m = material_from_flags(flags);
      if (faulty || bad_bottom) {
        ADD_FAILURE() << "built a faulty stack: " << escaped(arguments);
        continue;
      }
      ++built;
      const std::vector<StackedLayer> layers = stack_layers(m);
      ASSERT_EQ(layers.size(), count) << escaped(arguments);
      for (std::size_t i = 0; i < count; ++i) {
        EXPECT_EQ(layers[i].tau, expected[i].tau) << i << " " << escaped(arguments);
        EXPECT_EQ(layers[i].albedo, expected[i].albedo) << i << " " << escaped(arguments);
        EXPECT_EQ(layers[i].g, expected[i].g) << i << " " << escaped(arguments);
        EXPECT_EQ(layers[i].interface, expected[i].interface) << i << " " << escaped(arguments);
      }
    } catch (const std::exception& error) {
      const std::string message = error.what();
      ++refused;
      if (bad_bottom) {
        EXPECT_TRUE(message.starts_with("bottom-eta = ")) << message << " for " << escaped(arguments);
      } else if (!faulty) {
        ADD_FAILURE() << "refused a valid stack (" << message << "): " << escaped(arguments);
      } else {
        EXPECT_TRUE(message.starts_with("layer " + std::to_string(*faulty + 1) + ": "))
            << message << " for " << escaped(arguments);
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      }
    }
  }
  EXPECT_GT(built, 500);
  EXPECT_GT(refused, 1000);
}

}  // namespace
}  // namespace skinlayer::cli
