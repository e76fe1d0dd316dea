// Circles as quads, one instance per circle, covering the circle, its stroke and the
// antialiased rim.

layout(location = 0) in vec2 a_center;  // local coordinates
layout(location = 1) in float a_radius; // local units

uniform float u_half_width;  // of the stroke, pixels

out vec2 v_offset;          // from the centre, pixels
flat out float v_radius;    // pixels
flat out float v_dash_period;

void main() {
  vec2 center = local_to_pixels(a_center);
  float radius = a_radius * abs(u_scale.x);
  float reach = radius + u_half_width + 1.0;
  vec2 corner = strip_corner() * 2.0 - 1.0;
  v_offset = corner * reach;
  v_radius = radius;
  // Stretch the dash pattern so that a whole number of periods fits the circumference:
  // no half dash where the arc length wraps round.
  vec2 pattern = dash_pattern(2.0 * u_half_width);
  float circumference = 6.28318531 * radius;
  v_dash_period = max(circumference / max(1.0, floor(circumference / (pattern.x + pattern.y) + 0.5)), 1e-3);
  gl_Position = pixels_to_clip(center + v_offset);
}
