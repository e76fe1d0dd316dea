// Text and panels in pixels: one instance per rectangle, textured from the font atlas.
// Glyphs sample their coverage from it; plain and gradient rectangles sample a white patch.

layout(location = 0) in vec4 a_rectangle;  // x0, y0, x1, y1 in pixels (y down)
layout(location = 1) in vec4 a_texture;    // u0, v0, u1, v1 in the atlas
layout(location = 2) in vec4 a_top_color;
layout(location = 3) in vec4 a_bottom_color;

out vec2 v_texture;
out vec4 v_color;

void main() {
  vec2 corner = strip_corner();
  v_texture = mix(a_texture.xy, a_texture.zw, corner);
  v_color = mix(a_top_color, a_bottom_color, corner.y);
  gl_Position = pixels_to_clip(mix(a_rectangle.xy, a_rectangle.zw, corner));
}
