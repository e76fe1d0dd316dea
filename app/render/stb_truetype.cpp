// The one place the implementations of stb_truetype and stb_rect_pack are compiled
// (libstb-dev ships them as headers).
#define STB_RECT_PACK_IMPLEMENTATION
#define STB_TRUETYPE_IMPLEMENTATION
#include "stb_truetype.hpp"
