// The mesh's triangles, drawn unindexed, three vertices each. Each corner gets its
// barycentric coordinate from its place in the triangle (gl_VertexID % 3) and scales it by
// its height over the opposite edge (computed with the vertices, in local units), so the
// interpolated value is each pixel's distance to the three edges, in pixels, exactly.
//
// This pair of shaders draws a million triangles per frame, where llvmpipe runs the fragment
// shader for many more pixels than the triangles cover (it shades 2x2 quads, most of them
// partly outside a tiny triangle): everything that is constant over a triangle is worked
// out here, once per corner, and the fragment shader is a handful of operations. (Finding
// the distances from derivatives of the barycentric coordinates in the fragment shader
// instead costs about 10% more per frame on llvmpipe, measured at a million triangles.)

layout(location = 0) in vec2 a_position;  // local coordinates
layout(location = 1) in vec4 a_color;     // the triangle's fill (same at its 3 corners)
layout(location = 2) in float a_height;   // of this corner over the opposite edge, local units
layout(location = 3) in float a_size;     // sqrt(2 * the triangle's area), local units

uniform float u_fill_on;  // 1: draw the fill colours; 0: transparent inside
uniform vec4 u_edge;      // the edge colour, premultiplied (zero when edges are off)

noperspective out vec3 v_edge_distance;  // to the edges opposite corners 0, 1, 2, in pixels
flat out vec4 v_fill;                    // premultiplied
flat out vec4 v_toward_edge;             // (edge over fill) - fill, times the edge's fading

void main() {
  int corner = gl_VertexID % 3;
  float pixels_per_unit = abs(u_scale.x);
  v_edge_distance = vec3(corner == 0, corner == 1, corner == 2) * (a_height * pixels_per_unit);

  // Small triangles would be all edge (a million triangles on a 1080p picture are about two
  // pixels each), so the edges fade as the triangle gets small on screen: a dense mesh reads
  // as its fill colours with a light texture of edges, not as a dark blob. `size` is the
  // side of a right isosceles triangle of the same area (slivers count as small); the edges
  // are full from 14 px up and fade linearly to a tenth at 2 px and below.
  float fade = clamp(0.075 * a_size * pixels_per_unit - 0.05, 0.1, 1.0);

  v_fill = vec4(a_color.rgb * a_color.a, a_color.a) * u_fill_on;
  v_toward_edge = (u_edge - v_fill * u_edge.a) * fade;
  gl_Position = pixels_to_clip(local_to_pixels(a_position));
}
