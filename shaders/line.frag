// A thick segment with round caps: its distance field, antialiased over a pixel; dashes by
// arc length from the segment's start.

in vec2 v_local;
flat in float v_length;

uniform vec4 u_color;
uniform float u_half_width;
uniform float u_dashed;  // 1: dashed

out vec4 fragment;

void main() {
  float beyond_ends = max(-v_local.x, v_local.x - v_length);
  float distance_px = length(vec2(max(beyond_ends, 0.0), v_local.y));
  float alpha = coverage(u_half_width - distance_px);
  if (u_dashed > 0.5) {
    vec2 pattern = dash_pattern(2.0 * u_half_width);
    alpha *= dash_coverage(v_local.x, pattern.x, pattern.x + pattern.y);
  }
  fragment = premultiplied(u_color) * alpha;
}
