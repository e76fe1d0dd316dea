// The overlays' filled triangles (highlighted faces, triangle shapes), drawn unindexed, three
// vertices each; each corner's barycentric coordinate comes from its place in the triangle
// (gl_VertexID % 3).

layout(location = 0) in vec2 a_position;  // local coordinates
layout(location = 1) in vec4 a_color;     // the triangle's colour (same at its 3 corners)

noperspective out vec2 v_barycentric;  // of corners 0 and 1
flat out vec4 v_color;

void main() {
  int corner = gl_VertexID % 3;
  v_barycentric = vec2(corner == 0, corner == 1);
  v_color = a_color;
  gl_Position = pixels_to_clip(local_to_pixels(a_position));
}
