// Copies a texture to the viewport.
in vec2 v_uv;
uniform sampler2D u_source;
out vec4 o_color;
void main() { o_color = texture(u_source, v_uv); }
