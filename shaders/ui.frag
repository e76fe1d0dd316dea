in vec2 v_texture;
in vec4 v_color;

uniform sampler2D u_atlas;  // one channel: coverage

out vec4 fragment;

void main() { fragment = premultiplied(v_color) * texture(u_atlas, v_texture).r; }
