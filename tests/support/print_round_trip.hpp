#pragma once
// How far an image seen back through a print map is from the design it started as: for every
// pixel the formed part covers (opaque) whose colour differs from the design's, the distance in
// pixels (Chebyshev) to the nearest design pixel of its colour.
#include <algorithm>
#include <cstdint>

#include "fabform/io/png_image.hpp"

namespace fabform::test {

struct RoundTrip {
  int covered = 0;   // opaque pixels of the image seen back
  int wrong = 0;     // of them, of another colour than the design there
  int worst_px = 0;  // the farthest of those from a design pixel of their colour
};

inline bool same_colour(const std::uint8_t* a, const std::uint8_t* b) { return std::equal(a, a + 3, b); }

// The Chebyshev distance from (c, r) to the nearest pixel of `image` with this colour (up to 50).
inline int distance_to_colour(const Image& image, int c, int r, const std::uint8_t* colour) {
  for (int d = 0; d < 50; ++d)
    for (int dr = -d; dr <= d; ++dr)
      for (int dc = -d; dc <= d; ++dc) {
        const int rr = std::clamp(r + dr, 0, image.height - 1), cc = std::clamp(c + dc, 0, image.width - 1);
        if (same_colour(colour, image.pixel(cc, rr))) return d;
      }
  return 50;
}

inline RoundTrip round_trip(const Image& design, const Image& back) {
  RoundTrip trip;
  for (int r = 0; r < back.height; ++r)
    for (int c = 0; c < back.width; ++c) {
      if (back.pixel(c, r)[3] != 255) continue;
      ++trip.covered;
      if (same_colour(back.pixel(c, r), design.pixel(c, r))) continue;
      ++trip.wrong;
      trip.worst_px = std::max(trip.worst_px, distance_to_colour(design, c, r, back.pixel(c, r)));
    }
  return trip;
}

}  // namespace fabform::test
