// The probe: one sample of the vector per point, for tests that compare every backend's point
// location with brute force and for pathlines, whose host-side RK4 samples two snapshots per
// stage. It reuses the tracing bindings, AMRSTREAM_BINDING_TRACE_PROBE_POINTS holding the points
// (probePoints, cell units, already wrapped; AMRSTREAM_PROBE_POINTS defined before
// amr_buffers.glsl); the region found (-1 for none) goes to outRegions and the vector to
// outVectors, NaN where the sample is located but invalid. What outRegions holds when the probe
// starts (a region of this volume or -1) is each point's region hint (sampler.glsl): a
// particle's next sample mostly falls in its last region, and the answer is the same either way.
#ifdef AMRSTREAM_PROBE_POINTS
void probeLocation(uint pointIndex) {
  const int hint = outRegions[pointIndex];
  if (hint >= 0) {
    cachedRegionId = hint;
    cachedRegion = regions[hint];
  }
  const VectorSample s = sampleVector(ivec3(0), probePoints[pointIndex]);
  outRegions[pointIndex] = s.located ? s.region : -1;
  outVectors[pointIndex] = s.valid ? s.value : vec3(uintBitsToFloat(0x7fc00000u));
}
#endif

#ifdef AMRSTREAM_PROBE_GRID
// The grid probe: the vector at pixel (x, y) of probeGrid, at outVectors[x + width y] (NaN where
// the sample is not valid); the device twin of flow::sampleGrid over a slice's pixel centres.
void probeGridPoint(uvec2 pixel) {
  precise const vec3 along = probeGrid.originOffset + float(pixel.x) * probeGrid.stepX +
                             float(pixel.y) * probeGrid.stepY;
  const vec3 whole = floor(along);
  precise const vec3 offset = along - whole;
  const ivec3 anchor = wrapPeriodic(probeGrid.originAnchor + ivec3(whole), offset);
  const VectorSample s = sampleVector(anchor, offset);
  outVectors[pixel.x + probeGrid.width * pixel.y] =
      s.valid ? s.value : vec3(uintBitsToFloat(0x7fc00000u));
}
#endif
