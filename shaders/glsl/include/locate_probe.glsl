// The point-location probe: locateRegion() for one point, for tests that compare every backend's
// point location with brute force. It reuses the tracing bindings: the points are in the seed
// buffer (cell units) and the region ids (-1 for none) go to the reason buffer.
void probeLocation(uint pointIndex) { reasons[pointIndex] = locateRegion(seeds[pointIndex]); }
