// The one definition of stb_image (Debian's libstb-dev): PNG and TGA decoding from memory.
#define STB_IMAGE_IMPLEMENTATION
#include "stb_image_decoder.hpp"
