// The BAKE_grooves package as the shader reads it (formats/include/bake_formats/grooves.h): every
// bufferView bound as it is, as a std430 storage buffer, plus a small uniform block with the grid
// header. Stored positions are cell-local fp32 offsets from an anchor cell; rebuilt here relative to
// the fragment's footprint centre F with exact integer cell offsets (seed 000 §4.1 grid, kept precise
// on large domains), so everything downstream works in small coordinates around F.
#ifndef BAKE_GROOVES_PACKAGE_GLSL
#define BAKE_GROOVES_PACKAGE_GLSL

struct GroovePrimitive {
  ivec4 header;        // anchor column, row, groove, flags
  vec4 ends;           // a, b (cell-local)
  vec4 arc;            // centre (cell-local), radius, start angle
  vec4 measure;        // sweep, arcStart, length, 0
  vec4 jointPoints;    // start joint point, end joint point (cell-local)
  vec4 jointNormals;   // start normal, end normal (into the primitive)
};
struct GrooveRecord {
  ivec4 anchor;
  uvec4 info;          // kind, primitive 0, primitive 1, 0
  vec4 point;
  vec4 box;            // lower, upper (cell-local)
};
struct GrooveInfo {
  uvec4 indices;       // profile, material, first primitive, primitive count
  uvec4 kind;          // flags (closed), perturbation kind
  vec4 perturbation;   // amplitude, wavelength, phase
  vec4 bounds;         // wmax, hmax, dmax
};
struct GrooveProfile {
  uvec4 points;        // first point, count, symmetric
  vec4 bounds;
};
struct GrooveMaterial {
  vec4 albedo;         // rgb, shininess
  vec4 specular;       // rgb, has mirror
  vec4 mirror;         // rgb
};
struct FarClass {
  uvec4 info;          // profile, material, representative primitive, 0
  vec4 direction;      // unit tangent u, v; the profile's wmax; 0
};

layout(std430, binding = 0) readonly buffer CellStart { uint cellStart[]; };
layout(std430, binding = 1) readonly buffer PrimitiveRefs { uint primitiveRefs[]; };
layout(std430, binding = 2) readonly buffer RecordStart { uint recordStart[]; };
layout(std430, binding = 3) readonly buffer RecordRefs { uint recordRefs[]; };
layout(std430, binding = 4) readonly buffer Records { GrooveRecord records[]; };
layout(std430, binding = 5) readonly buffer Primitives { GroovePrimitive primitives[]; };
layout(std430, binding = 6) readonly buffer Grooves { GrooveInfo grooves[]; };
layout(std430, binding = 7) readonly buffer Profiles { GrooveProfile profiles[]; };
layout(std430, binding = 8) readonly buffer ProfilePoints { vec2 profilePoints[]; };
layout(std430, binding = 9) readonly buffer Materials { GrooveMaterial materials[]; };
// The far level (far_level.glsl; version 2 packages, else 16 zero bytes and uFarCells.z = 0).
layout(std430, binding = 10) readonly buffer FarClasses { FarClass farClasses[]; };
layout(std430, binding = 11) readonly buffer FarTable { double farTable[]; };

layout(std140, binding = 0) uniform GrooveHeader {
  vec4 uDomainCell;    // domain U, V; cell size u, v
  vec4 uOriginBounds;  // grid origin u, v; 0, 0
  vec4 uBounds;        // wmax, hmax, dmax, 0
  ivec4 uCells;        // columns, rows, wrap (0/1), base material
  ivec4 uCounts;       // primitives, records, 0, 0
  vec4 uFarCell;       // far level cell size u, v; 0, 0
  ivec4 uFarCells;     // far level columns, rows, classes (0: none), 0
};

const float kPi = 3.14159265358979;
// Beyond any section coordinate (sizes of a domain at most) yet far from overflow: stands in for the
// CPU's infinity, which the GLSL compiler may not keep through constant folding or fast math.
const float kInfinity = 1.0e20;
const uint kPrimitiveArc = 1u;
const uint kPerturbationScale = 1u;
const uint kPerturbationOffset = 2u;
const uint kGrooveClosed = 1u;

vec2 domainSize() { return uDomainCell.xy; }
vec2 cellSize() { return uDomainCell.zw; }
ivec2 cellCounts() { return uCells.xy; }
bool wrapRepeat() { return uCells.z != 0; }
int baseMaterial() { return uCells.w; }
int recordCount() { return uCounts.y; }

// The footprint centre's cell and its offset from that cell's corner.
ivec2 gFragCell;
vec2 gFragLocal;

void setFootprintCentre(vec2 centre) {
  vec2 fromOrigin = centre - uOriginBounds.xy;
  gFragCell = ivec2(floor(fromOrigin / cellSize()));
  gFragLocal = fromOrigin - vec2(gFragCell) * cellSize();
}

// A stored point (anchor cell, cell-local offset) relative to F, its copy moved by `shift` cells.
vec2 relativeToCentre(ivec2 anchor, ivec2 shift, vec2 local) {
  return (local - gFragLocal) + vec2(anchor + shift - gFragCell) * cellSize();
}

#endif
