// A circle: an antialiased ring (the stroke, centred on the circle), optionally filled.

in vec2 v_offset;
flat in float v_radius;
flat in float v_dash_period;

uniform vec4 u_color;        // the stroke
uniform vec4 u_fill;         // the inside (alpha 0: none)
uniform float u_half_width;
uniform float u_dashed;

out vec4 fragment;

void main() {
  float from_center = length(v_offset);
  float stroke = coverage(u_half_width - abs(from_center - v_radius));
  if (u_dashed > 0.5) {
    vec2 pattern = dash_pattern(2.0 * u_half_width);
    float dash = pattern.x * v_dash_period / (pattern.x + pattern.y);
    float arc = (atan(v_offset.y, v_offset.x) + 3.14159265) * v_radius;
    stroke *= dash_coverage(arc, dash, v_dash_period);
  }
  float inside = coverage(v_radius - from_center);
  fragment = over(premultiplied(u_color) * stroke, premultiplied(u_fill) * inside);
}
