// Point location for the `compute` backend: descent of the regions' kd-tree, built on the host
// (src/bricks/region_builder.hpp). Stackless: every point takes exactly one path.

// The tracer binds the tree at AMRSTREAM_LOCATE_BINDING; other kernels may define
// AMRSTREAM_TREE_BINDING first.
#ifndef AMRSTREAM_TREE_BINDING
#define AMRSTREAM_TREE_BINDING AMRSTREAM_LOCATE_BINDING
#endif
layout(scalar, set = 0, binding = AMRSTREAM_TREE_BINDING) readonly buffer RegionTreeBuffer { RegionTreeNode tree[]; };

int locateInRegions(ivec3 k) {
  uint node = 0;
  while (tree[node].axis != AMRSTREAM_TREE_LEAF) {
    const RegionTreeNode n = tree[node];
    node = k[n.axis] < n.split ? n.child : n.child + 1;
  }
  return tree[node].child == AMRSTREAM_NO_REGION ? -1 : int(tree[node].child);
}
