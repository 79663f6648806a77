// G-code programs read back as motion (io/gcode.hpp says which subset): a
// line at a time, comments removed, words (a letter and a number) taken in
// the NIST order that matters here: the modes first (units, plane, distance
// and arc-centre modes), then the motion with the block's X Y Z I J.
#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "casteljau/io/gcode.hpp"
#include "casteljau/io/tolerance.hpp"

namespace casteljau {
namespace {

/// A word of a block: its letter (upper case) and its number.
struct Word {
  char letter;
  double value;
};

/// The words of one line, comments removed; an error names what is wrong.
Expected<std::vector<Word>> words_of(std::string_view line) {
  std::vector<Word> words;
  std::size_t i = 0;
  while (i < line.size()) {
    const char c = line[i];
    if (c == ';') break;
    if (c == '(') {
      const std::size_t close = line.find(')', i);
      if (close == std::string_view::npos) return Error{"a comment '(' without its ')'"};
      i = close + 1;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(c)) || c == '%') {
      ++i;
      continue;
    }
    if (!std::isalpha(static_cast<unsigned char>(c))) return Error{fmt::format("'{}' where a word's letter belongs", c)};
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    ++i;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t end = i;
    while (end < line.size() && (std::isdigit(static_cast<unsigned char>(line[end])) || line[end] == '.' ||
                                 line[end] == '-' || line[end] == '+'))
      ++end;
    const std::string number(line.substr(i, end - i));
    char* stop = nullptr;
    const double value = number.empty() ? NAN : std::strtod(number.c_str(), &stop);
    if (number.empty() || stop != number.c_str() + number.size() || !std::isfinite(value))
      return Error{fmt::format("{}{} is not a word (a letter and a finite number)", letter, number)};
    words.push_back({letter, value});
    i = end;
  }
  return words;
}

/// The code of a G or M word: G1 is 10, G91.1 is 911 (tenths), so that
/// codes compare as integers.
int code_of(double value) { return static_cast<int>(std::lround(value * 10.0)); }

}  // namespace

Expected<GcodeReading> read_gcode(std::string_view text) {
  GcodeReading reading;
  std::optional<GcodeUnits> units;
  GcodeMove::Kind motion = GcodeMove::Kind::rapid;
  std::array<double, 3> position{};
  bool moved = false;
  std::size_t number = 0;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    ++number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const auto failed = [&](const std::string& what) { return Error{fmt::format("line {}: {}", number, what)}; };
    auto words = words_of(line);
    if (!words) return failed(words.error().message);
    std::optional<double> axis[3], offset[2];
    bool ends = false, motion_given = false;
    for (const Word& word : *words) {
      const int code = code_of(word.value);
      switch (word.letter) {
        case 'G':
          switch (code) {
            case 0: case 10: case 20: case 30:
              motion = code == 0 ? GcodeMove::Kind::rapid : code == 10 ? GcodeMove::Kind::line
                       : code == 20 ? GcodeMove::Kind::clockwise_arc : GcodeMove::Kind::counterclockwise_arc;
              motion_given = true;
              break;
            case 200: case 210: {
              const GcodeUnits now = code == 200 ? GcodeUnits::inches : GcodeUnits::millimetres;
              if (moved && units && *units != now) return failed("the units change after the first move");
              units = now;
              break;
            }
            case 170: case 900: case 911: case 940: case 640: case 610: break;
            default:
              return failed(fmt::format("G{:g} is not read (read: G0 G1 G2 G3, G17, G20 G21, G90, G91.1, G94, G61, "
                                        "G64)", word.value));
          }
          break;
        case 'M':
          if (code == 20 || code == 300) ends = true;
          else if (code != 30 && code != 40 && code != 50 && code != 70 && code != 80 && code != 90)
            return failed(fmt::format("M{:g} is not read (read: M2 M30, and M3 M4 M5 M7 M8 M9 ignored)", word.value));
          break;
        case 'X': case 'Y': case 'Z': axis[word.letter - 'X'] = word.value; break;
        case 'I': case 'J': offset[word.letter - 'I'] = word.value; break;
        case 'R': return failed("an arc in the R form is not read (only I J centres)");
        case 'N': case 'F': case 'S': case 'T': case 'P': case 'Q': break;
        default: return failed(fmt::format("the word {}{:g} is not read", word.letter, word.value));
      }
    }
    const bool arc = motion == GcodeMove::Kind::clockwise_arc || motion == GcodeMove::Kind::counterclockwise_arc;
    if ((offset[0] || offset[1]) && !arc) return failed("I or J without an arc (G2 or G3)");
    if (axis[0] || axis[1] || axis[2] || (arc && motion_given)) {
      if (reading.moves.size() >= static_cast<std::size_t>(tolerances::kGcodeMostMoves))
        return failed(fmt::format("more than {} moves", tolerances::kGcodeMostMoves));
      GcodeMove move;
      move.kind = motion;
      move.from = position;
      move.line = number;
      for (int k = 0; k < 3; ++k) move.to[k] = axis[k].value_or(position[k]);
      if (arc) {
        if (!offset[0] && !offset[1]) return failed("an arc without its centre (I J)");
        move.centre = Vec2{{position[0] + offset[0].value_or(0.0), position[1] + offset[1].value_or(0.0)}};
      }
      reading.moves.push_back(move);
      position = move.to;
      moved = true;
    }
    if (ends) break;
  }
  reading.units = units.value_or(GcodeUnits::millimetres);
  return reading;
}

}  // namespace casteljau
