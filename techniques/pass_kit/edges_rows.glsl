// supersample_edges' storage buffer, laid out by std430 at the offsets
// PassKit reads: the head, which edges_list.comp's step 1 writes (the
// entries' total at 0; the scatter's indirect dispatch at 4; the packed
// pass's indirect draw, a DrawArraysIndirectCommand, at 16; its rectangles,
// x0 y0 x1 y1 in pixels of the packed target, at 32), then each row's first
// entry from 64.
layout(std430, binding = 0) buffer EdgeRows {
  uint total;
  uint dispatch_x, dispatch_y, dispatch_z;
  uvec4 draw_command;
  ivec4 cover[2];
  uint first[];
};
