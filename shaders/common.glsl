// Shared by every meshstep shader. shader_program.cpp compiles each shader as
//   #version 330 core, #define MESHSTEP_VERTEX_SHADER (or _FRAGMENT_), this file, the shader.
//
// Coordinates. The CPU turns world points into "local" floats (relative to an origin, scaled
// in double precision: world_frame.hpp), so the GPU only sees well-conditioned numbers.
// local_to_pixels() maps them to pixels of the picture: origin top-left, y down, as in
// images. Every size on screen (stroke widths, marker sizes, text) is in pixels.
//
// Colours. Uniform and vertex colours are straight (not premultiplied) RGBA; every fragment
// shader writes premultiplied colour, blended with ONE, ONE_MINUS_SRC_ALPHA, so that a
// translucent background still composes correctly.

// Dashes of a stroke `width` pixels wide: (dash length, gap length), long enough to read at
// any width.
vec2 dash_pattern(float width) { return vec2(max(3.0 * width, 4.0), max(2.0 * width, 3.0)); }

#ifdef MESHSTEP_VERTEX_SHADER

uniform vec2 u_viewport;  // the picture's size in pixels
uniform vec2 u_scale;     // pixels per local unit, in x and y (negative y: world y points up)
uniform vec2 u_offset;    // the pixel of local (0, 0)

vec2 local_to_pixels(vec2 local) { return local * u_scale + u_offset; }

// Pixel row 0 goes to framebuffer row 0: the framebuffer holds the picture top row first,
// as images are stored, so reading it back needs no flip (the blit to a window flips).
vec4 pixels_to_clip(vec2 pixel) {
  return vec4(2.0 * pixel.x / u_viewport.x - 1.0, 2.0 * pixel.y / u_viewport.y - 1.0, 0.0, 1.0);
}

// The corner of a quad drawn as a 4-vertex triangle strip: (0,0), (1,0), (0,1), (1,1).
vec2 strip_corner() { return vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1)); }

#endif

#ifdef MESHSTEP_FRAGMENT_SHADER

vec4 premultiplied(vec4 straight) { return vec4(straight.rgb * straight.a, straight.a); }

// How much of a pixel a shape covers, when the pixel's centre lies `inside` pixels within
// the shape's edge (negative: outside): a 1-pixel-wide linear ramp, the antialiasing of
// every edge drawn here.
float coverage(float inside) { return clamp(inside + 0.5, 0.0, 1.0); }

// `top` drawn over `bottom`, both premultiplied.
vec4 over(vec4 top, vec4 bottom) { return top + bottom * (1.0 - top.a); }

// How much of the pixel at arc length `s` (pixels along the stroke) falls on a dash; dashes
// start at s = 0 and repeat every `period` pixels (dash_pattern's sum, or a stretched one).
float dash_coverage(float s, float dash, float period) {
  float t = mod(s, period);
  if (t < dash) return coverage(min(t, dash - t));
  return coverage(-min(t - dash, period - t));
}

#endif
