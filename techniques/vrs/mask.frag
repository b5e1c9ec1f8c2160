// The stencil mask of a rate class: drawn over the class's rectangles only
// (pass_kit/rects.vert); the pass state marks every fragment, colour is off.
out vec4 o_color;
void main() { o_color = vec4(0.0); }
