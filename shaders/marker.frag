// A marker from its signed distance field (negative inside), in pixels: the inside filled,
// the outline stroked on the boundary. A cross is only a stroke.

in vec2 v_offset;

uniform int u_kind;          // 0 disc, 1 ring, 2 square, 3 cross, 4 diamond (scene::Marker)
uniform float u_size;
uniform float u_half_width;
uniform vec4 u_color;        // the outline
uniform vec4 u_fill;         // the inside (alpha 0: none)

out vec4 fragment;

float distance_to_segment(vec2 p, vec2 a, vec2 b) {
  vec2 ab = b - a;
  float t = clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
  return length(p - a - ab * t);
}

void main() {
  float r = 0.5 * u_size;
  vec2 p = v_offset;
  if (u_kind == 3) {  // cross: the two diagonals of a square a little smaller than the size
    float arm = 0.75 * r;
    float d = min(distance_to_segment(p, vec2(-arm), vec2(arm)), distance_to_segment(p, vec2(-arm, arm), vec2(arm, -arm)));
    fragment = premultiplied(u_color) * coverage(u_half_width - d);
    return;
  }
  float sdf;
  if (u_kind == 2) {  // square
    vec2 q = abs(p) - vec2(r);
    sdf = length(max(q, 0.0)) + min(max(q.x, q.y), 0.0);
  } else if (u_kind == 4) {  // diamond: |x| + |y| <= r, as a distance
    sdf = (abs(p.x) + abs(p.y) - r) * 0.70710678;
  } else {  // disc and ring
    sdf = length(p) - r;
  }
  vec4 stroke = premultiplied(u_color) * coverage(u_half_width - abs(sdf));
  vec4 fill = premultiplied(u_fill) * coverage(-sdf);
  fragment = over(stroke, fill);
}
