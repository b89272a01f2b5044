// Paintstroke patches carry no vertex attributes: the control stage fetches its segment's four
// control points from the storage buffers. This stage only names the segment of its patch, from the
// vertex index (4 per patch); gl_PrimitiveID is not used for that, as a driver may restart it when
// it splits a large draw into batches.
out uint vSegment;

void main() {
  vSegment = uint(gl_VertexID) / 4u;
  gl_Position = vec4(0.0);
}
