// PLACEHOLDER (replaced by the ray-traced reference): keeps the library linking meanwhile.
#include "groove/reference.h"
namespace bake::groove {
struct ReferenceSurface::Impl {};
ReferenceSurface::ReferenceSurface(const GrooveScene&) : impl_(new Impl) {}
ReferenceSurface::~ReferenceSurface() { delete impl_; }
double ReferenceSurface::height(Vec2) const { return 0; }
bool ReferenceSurface::intersect(const Vec3&, const Vec3&, Hit&) const { return false; }
Rgb referenceRadiance(const ReferenceSurface&, const GrooveScene&, Vec2, const Vec3&, const Lighting&) { return {0, 0, 0}; }
RgbImage renderReference(const GrooveScene&, const View&, const Lighting&, const ReferenceSettings&) { return {}; }
}  // namespace bake::groove
