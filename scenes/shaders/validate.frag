// Compiles a scene's shading function on its own, to report errors at load.
out vec4 foveate_validate_out;
void main() { foveate_validate_out = scene_shade(gl_FragCoord.xy); }
