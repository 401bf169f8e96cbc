// Point location for the `compute` backend: descent of the regions' kd-tree, built on the host
// (src/bricks/region_builder.hpp), from the start node of the point's cell in the grid at the
// buffer's head (src/bricks/descent_tree.hpp). Stackless: every point takes exactly one path.

// The tracer binds the tree at AMRSTREAM_BINDING_TRACE_LOCATE; other kernels may define
// AMRSTREAM_TREE_BINDING first.
#ifndef AMRSTREAM_TREE_BINDING
#define AMRSTREAM_TREE_BINDING AMRSTREAM_BINDING_TRACE_LOCATE
#endif
layout(scalar, set = 0, binding = AMRSTREAM_TREE_BINDING) readonly buffer RegionTreeBuffer {
  RegionTreeGrid treeGrid;
  RegionTreeNode tree[];
};

// Twin of DescentTree::locate().
int locateInRegions(ivec3 k) {
  const uvec3 cell = uvec3(clamp(k, treeGrid.lower, treeGrid.last) - treeGrid.lower) >> treeGrid.shift;
  RegionTreeNode node = tree[cell.x + treeGrid.cells.x * (cell.y + treeGrid.cells.y * cell.z)];
  while (node.axis != AMRSTREAM_TREE_LEAF) {
    // Selected, not indexed: a vector indexed by a run-time value goes to local memory.
    const int coordinate = node.axis == 0u ? k.x : (node.axis == 1u ? k.y : k.z);
    node = tree[coordinate < node.split ? node.child : node.child + 1u];
  }
  return node.child == AMRSTREAM_NO_REGION ? -1 : int(node.child);
}
