// Dear ImGui's triangles (the viewer's panels), as its draw lists give them: positions in
// pixels of the window, texture coordinates into the font atlas (or a picture), a colour.

layout(location = 0) in vec2 a_position;
layout(location = 1) in vec2 a_uv;
layout(location = 2) in vec4 a_color;

uniform vec2 u_window;   // pixels
uniform float u_y_down;  // 1: the target's first row is the top (off screen); -1: a window

out vec2 v_uv;
out vec4 v_color;

void main() {
  v_uv = a_uv;
  v_color = a_color;
  vec2 clip = 2.0 * a_position / u_window - 1.0;
  gl_Position = vec4(clip.x, u_y_down * clip.y, 0.0, 1.0);
}
