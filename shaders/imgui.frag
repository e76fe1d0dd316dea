// ImGui's colours are straight alpha; the output is premultiplied like every meshstep shader.

in vec2 v_uv;
in vec4 v_color;

uniform sampler2D u_texture;

out vec4 fragment;

void main() { fragment = premultiplied(v_color * texture(u_texture, v_uv)); }
