// Triangle's switch letters (triangle_switches.hpp). A number follows a switch directly:
// digits and '.', and for an area an exponent ("a1e-3"); an 'e' not followed by a digit or a
// sign and digit is the edges switch ("a0.5e" is an area of 0.5 and edges).
#include "triangle_switches.hpp"

#include <algorithm>
#include <cctype>

namespace meshstep::python {
namespace {

bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// The number starting at text[i] (possibly empty); i is left after it.
std::string read_number(std::string_view text, std::size_t& i, bool exponent) {
  const std::size_t start = i;
  while (i < text.size() && (digit(text[i]) || text[i] == '.')) ++i;
  if (exponent && i > start && i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < text.size() && (text[j] == '-' || text[j] == '+')) ++j;
    if (j < text.size() && digit(text[j])) {
      i = j;
      while (i < text.size() && digit(text[i])) ++i;
    }
  }
  return std::string(text.substr(start, i - start));
}

[[noreturn]] void refuse(char letter, std::string_view text, const std::string& why) {
  throw std::invalid_argument("switch '" + std::string(1, letter) + "' in '" + std::string(text) + "' " + why);
}

}  // namespace

TriangleSwitches parse_triangle_switches(std::string_view text) {
  TriangleSwitches s;
  std::size_t i = 0;
  while (i < text.size()) {
    const char letter = text[i++];
    switch (letter) {
      case 'p': s.pslg = true; break;
      case 'q':
        s.quality = true;
        s.min_angle = read_number(text, i, false);
        break;
      case 'a': {
        const std::string number = read_number(text, i, true);
        if (number.empty()) s.regional_area = true;
        else s.max_area = number;
        break;
      }
      case 'c': s.convex_hull = true; break;
      case 'r': s.refine_mesh = true; break;
      case 'e': s.edges = true; break;
      case 'n': s.neighbors = true; break;
      case 'D': s.conforming = true; break;
      case 'S': s.max_steiner = read_number(text, i, false); break;
      case 'A': s.attributes = true; break;
      // Numbering from 0 is the only numbering here, and nothing is printed: z and Q ask for
      // what is done anyway (the triangle package adds them itself).
      case 'z': case 'Q': break;
      // Y: no Steiner point on the boundary's segments; YY (or more): on none.
      case 'Y': s.keep_segments = std::min(s.keep_segments + 1, 2); break;
      case 'o': case 'u': case 'F': case 'l': case 's': case 'i': case 'j': case 'v': case 'V': case 'I':
      case 'O': case 'P': case 'N': case 'E': case 'B': case 'X': case 'C': case 'g': case 'h': case 'w':
      case 'W': case 'L': case 'T': case 'k':
        refuse(letter, text,
               "is not supported by meshstep.triangulate (it takes p, q[ANGLE], a[AREA], a, c, r, e, n, D, Y, YY, S[N], "
               "A, and z and Q, which change nothing)");
      default:
        refuse(letter, text, "is not a switch (meshstep.triangulate takes p, q[ANGLE], a[AREA], a, c, r, e, n, D, "
                             "Y, YY, S[N], A, z, Q)");
    }
  }
  return s;
}

}  // namespace meshstep::python
