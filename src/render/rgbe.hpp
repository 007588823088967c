#pragma once
// One RGBE pixel (radiance_hdr.hpp) to linear RGB and back, and which scanlines may be run-length
// encoded; private to the render engine.
//
// Invariants: rgb_of(rgbe_of(c)) is within 1/256 of the largest channel of c; rgbe_of(rgb_of(p)) == p for
// every pixel with E > 0 whose largest mantissa is at least 128 (what rgbe_of writes), and (0,0,0,0) for
// E = 0.
#include <array>
#include <cstddef>
#include <cstdint>

namespace pbrfit::render {

using Rgbe = std::array<std::uint8_t, 4>;

std::array<float, 3> rgb_of(const Rgbe& pixel);
// c finite, >= 0, max < 2^127 (the caller checks).
Rgbe rgbe_of(const std::array<float, 3>& c);

// New-style run-length scanlines exist for these widths only.
inline bool run_length_width(std::size_t width) { return width >= 8 && width <= 0x7fff; }

}  // namespace pbrfit::render
