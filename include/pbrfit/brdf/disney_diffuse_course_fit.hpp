#pragma once
// The closed-form fits of Pesce & Iwanicki 2015, section 6.4, for the Disney diffuse environment lobe
// over roughness in [0, 1] and mu = n.v in [0, 1] (anchors to compare the integrated tables against):
//   beta = max(0, -0.2988 + 0.3775 (1 - mu) + 0.1372 roughness)
//   ZH0  = (-0.0913 + 0.3067 r) + (-0.6502 - 1.0803 r) m + (-0.5993 + 1.0632 r) m^2,  m = max(1 - mu, 0.5637)
//   ZH1  = (1.1635 - 0.0304 r + 0.0162 (1 - mu)) ZH0,   or the constant form 1.1564 ZH0
//   ZH2  = (0.5725 - 0.0569 r + 0.0386 (1 - mu)) ZH0,   or the constant form 0.5634 ZH0
// The coefficients are as printed in the course text (the ZH0 polynomial comes out negative there, so
// its sign convention or transcription differs from the SH normalization of spherical_harmonics.hpp; the
// ratios and beta are normalization-free).
namespace pbrfit::brdf {

double course_disney_beta(double roughness, double n_dot_v);
double course_disney_zh0(double roughness, double n_dot_v);
double course_disney_zh1_ratio(double roughness, double n_dot_v);  // ZH1 / ZH0, linear fit
double course_disney_zh2_ratio(double roughness, double n_dot_v);  // ZH2 / ZH0, linear fit

inline constexpr double course_disney_zh1_constant_ratio = 1.1564;
inline constexpr double course_disney_zh2_constant_ratio = 0.5634;

}  // namespace pbrfit::brdf
