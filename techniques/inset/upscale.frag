// The blurred periphery over the whole screen (bilinear upscale).
in vec2 v_uv;
uniform sampler2D u_periphery;
out vec4 o_color;
void main() { o_color = vec4(texture(u_periphery, v_uv).rgb, 1.0); }
