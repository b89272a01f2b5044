// Constants of scene descriptions (formats/scene.md), shared by the reader in libbake/pipe and the
// tools that plan, assemble and validate scenes.
#pragma once

namespace bake::format::scene {

inline constexpr int kVersion = 1;

// The on-screen size of a texel above which a TAM level is kept (formats/scene.md): a level whose
// texels are all smaller than half a pixel at the largest pixels per unit is never the finer of the
// two levels a trilinear lookup blends.
inline constexpr double kKeepLevelTexelPixels = 0.5;

// The name of the Ninja pool that serialises GL validation (one GL context at a time).
inline constexpr const char* kGlPool = "gl";

}  // namespace bake::format::scene
