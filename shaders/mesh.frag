// The mesh in one pass: each triangle's fill colour with its edges drawn over it, from the
// distances to the edges (mesh.vert). Each triangle draws half of the stroke on its side of
// every edge; the neighbour draws the other half.

noperspective in vec3 v_edge_distance;
flat in vec4 v_fill;
flat in vec4 v_toward_edge;

uniform float u_edge_half_width;  // pixels

out vec4 fragment;

void main() {
  float to_edge = min(v_edge_distance.x, min(v_edge_distance.y, v_edge_distance.z));
  fragment = v_fill + v_toward_edge * coverage(u_edge_half_width - to_edge);
}
