// stb_truetype, with stb_rect_pack in front of it so that glyph atlases are packed tightly
// (without it stb_truetype packs in plain rows). Include this, not the stb headers.
#pragma once

#include <stb/stb_rect_pack.h>
#include <stb/stb_truetype.h>
