// Portable names (export_names.hpp): what every export language accepts, and the closest such name for
// any text.
#include <catch2/catch_test_macros.hpp>

#include <string>

#include "pbrfit/gp/export_names.hpp"

using namespace pbrfit::gp;

TEST_CASE("portable names are identifiers of C++, HLSL and GLSL at once") {
  for (const char* name : {"y", "scale", "n_dot_v", "roughness2", "x_", "Albedo"}) CHECK(is_portable_name(name));
  for (const char* name : {"", "2x", "_x", "a__b", "gl_Position", "a-b", "a.b", "sin", "float", "half", "input",
                           "sample", "output", "main", "mad", "inversesqrt", "é"})
    CHECK_FALSE(is_portable_name(name));
}

TEST_CASE("any text becomes the closest portable name, and portable names stay as they are") {
  CHECK(portable_name("scale") == "scale");
  CHECK(portable_name("n_dot_v") == "n_dot_v");
  CHECK(portable_name("dfg/scale") == "dfg_scale");
  CHECK(portable_name("__a  b__") == "a_b_");
  CHECK(portable_name("2d") == "f2d");
  CHECK(portable_name("gl_x") == "fgl_x");
  CHECK(portable_name("float") == "float_");
  CHECK(portable_name("input") == "input_");
  CHECK(portable_name("") == "model");
  CHECK(portable_name("___") == "model");
  for (const char* text : {"", "-", "a b", "9", "gl_", "sin", "x\ny", "é", "__init__", "a__"})
    CHECK(is_portable_name(portable_name(text)));
}
