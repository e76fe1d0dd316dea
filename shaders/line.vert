// Thick lines as screen-space quads, one instance per segment: the quad covers the segment
// and its round caps, widened by a pixel for the antialiased rim. glLineWidth is not used:
// core profiles may only support width 1.
//
// The segment is first clipped to the picture (plus a margin), so a segment reaching far
// off screen still gives small, precise pixel coordinates.

layout(location = 0) in vec2 a_from;  // local coordinates
layout(location = 1) in vec2 a_to;

uniform float u_half_width;  // pixels

out vec2 v_local;        // (along the segment from its start, across it), pixels
flat out float v_length; // the whole segment's length, pixels

// The part of a -> b inside the rectangle [lo, hi], as parameters (t0, t1) along it; t0 > t1
// when the segment misses the rectangle.
vec2 clip_to_rectangle(vec2 a, vec2 b, vec2 lo, vec2 hi) {
  vec2 d = b - a;
  float t0 = 0.0, t1 = 1.0;
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0.0) {
      if (a[axis] < lo[axis] || a[axis] > hi[axis]) return vec2(1.0, 0.0);
    } else {
      float ta = (lo[axis] - a[axis]) / d[axis], tb = (hi[axis] - a[axis]) / d[axis];
      t0 = max(t0, min(ta, tb));
      t1 = min(t1, max(ta, tb));
    }
  }
  return vec2(t0, t1);
}

void main() {
  vec2 from = local_to_pixels(a_from), to = local_to_pixels(a_to);
  float reach = u_half_width + 1.0;  // the stroke's half width plus the antialiased rim
  vec2 along = to - from;
  float len = length(along);
  vec2 direction = len > 0.0 ? along / len : vec2(1.0, 0.0);
  vec2 normal = vec2(-direction.y, direction.x);

  vec2 margin = vec2(reach + 1.0);
  vec2 t = clip_to_rectangle(from, to, -margin, u_viewport + margin);
  if (t.x > t.y) {  // off screen: a degenerate quad draws nothing
    gl_Position = vec4(2.0, 2.0, 0.0, 1.0);
    v_local = vec2(0.0);
    v_length = 0.0;
    return;
  }
  // Extend the clipped part by the caps only where the segment really ends.
  float start = t.x * len - (t.x == 0.0 ? reach : 0.0);
  float end = t.y * len + (t.y == 1.0 ? reach : 0.0);

  vec2 corner = strip_corner();
  float s = mix(start, end, corner.y);
  float across = mix(-reach, reach, corner.x);
  v_local = vec2(s, across);
  v_length = len;
  gl_Position = pixels_to_clip(from + direction * s + normal * across);
}
