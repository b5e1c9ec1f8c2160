// Reconstruction, last pass, inside the native fovea: the shaded frame.
uniform sampler2D u_frame;
layout(early_fragment_tests) in;
out vec4 o_color;
void main() { o_color = vec4(texelFetch(u_frame, ivec2(gl_FragCoord.xy), 0).rgb, 1.0); }
