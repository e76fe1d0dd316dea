// Filled triangles of the overlays (highlighted faces, triangle shapes), usually translucent.
// Without multisampling their edges are smoothed from the inside: the pixels within half a
// pixel of an edge fade, from the distance given by the barycentric coordinates.

noperspective in vec2 v_barycentric;
flat in vec4 v_color;

uniform float u_smooth_edges;  // 1 when the framebuffer has a single sample

out vec4 fragment;

void main() {
  vec3 b = vec3(v_barycentric, 1.0 - v_barycentric.x - v_barycentric.y);
  vec3 distance_px = b / max(fwidth(b), vec3(1e-20));
  float to_edge = min(distance_px.x, min(distance_px.y, distance_px.z));
  float alpha = mix(1.0, coverage(to_edge), u_smooth_edges);
  fragment = premultiplied(v_color) * alpha;
}
