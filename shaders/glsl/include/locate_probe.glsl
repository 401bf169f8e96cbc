// The point-location probe: locateRegion() for one point, for tests that compare every backend's
// point location with brute force. It reuses the tracing bindings: the points are the positions
// of statesIn (cell units) and the region ids (-1 for none) go to outRegions.
void probeLocation(uint pointIndex) {
  outRegions[pointIndex] = locateRegion(statesIn[pointIndex].position);
}
