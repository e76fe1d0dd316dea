// Markers as quads, one instance per point, a fixed size in pixels whatever the zoom.

layout(location = 0) in vec2 a_position;  // local coordinates

uniform float u_size;        // across, pixels
uniform float u_half_width;  // of the outline, pixels

out vec2 v_offset;  // from the point, pixels

void main() {
  float reach = 0.5 * u_size + u_half_width + 1.0;
  v_offset = (strip_corner() * 2.0 - 1.0) * reach;
  gl_Position = pixels_to_clip(local_to_pixels(a_position) + v_offset);
}
