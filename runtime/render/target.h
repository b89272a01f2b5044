// An offscreen render target: a framebuffer object with a 16-bit (or 32-bit) float colour buffer (linear
// light, so EXR output keeps the full range) and a 24-bit depth buffer, read back as a top-row-first image.
#pragma once

#include "bake/core/status.h"
#include "bake/io/image.h"

namespace bake::play {

// Half floats are what EXR output keeps; full floats for measurements below half a half-float step
// (bench-groove compares with a reference whose noise floor can be 2e-5).
enum class ColourPrecision { Float16, Float32 };

class OffscreenTarget {
 public:
  static Result<OffscreenTarget> create(int width, int height, ColourPrecision precision = ColourPrecision::Float16);
  OffscreenTarget() = default;
  OffscreenTarget(OffscreenTarget&& other) noexcept;
  OffscreenTarget& operator=(OffscreenTarget&& other) noexcept;
  ~OffscreenTarget();

  void bind() const;
  Image readLinearRgba() const;  // top row first
  unsigned colourTexture() const { return colour_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void release();
  unsigned framebuffer_ = 0, colour_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0;
};

// Linear light to sRGB-encoded values (for 8/16-bit PNG), alpha untouched.
Image encodeSrgb(const Image& linear);

}  // namespace bake::play
