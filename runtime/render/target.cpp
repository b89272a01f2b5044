#include "render/target.h"

#include <GL/glcorearb.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace bake::play {

Result<OffscreenTarget> OffscreenTarget::create(int width, int height, ColourPrecision precision) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384) {
    return usageError("frame size " + std::to_string(width) + "x" + std::to_string(height) + " is out of range (1 to 16384)");
  }
  OffscreenTarget target;
  target.width_ = width;
  target.height_ = height;
  glCreateTextures(GL_TEXTURE_2D, 1, &target.colour_);  // a texture, so a window can present it
  glTextureStorage2D(target.colour_, 1, precision == ColourPrecision::Float32 ? GL_RGBA32F : GL_RGBA16F, width, height);
  glTextureParameteri(target.colour_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(target.colour_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glCreateRenderbuffers(1, &target.depth_);
  glNamedRenderbufferStorage(target.depth_, GL_DEPTH_COMPONENT24, width, height);
  glCreateFramebuffers(1, &target.framebuffer_);
  glNamedFramebufferTexture(target.framebuffer_, GL_COLOR_ATTACHMENT0, target.colour_, 0);
  glNamedFramebufferRenderbuffer(target.framebuffer_, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, target.depth_);
  const GLenum status = glCheckNamedFramebufferStatus(target.framebuffer_, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    return internalError("the offscreen framebuffer is incomplete (status 0x" + std::to_string(status) + ")");
  }
  return target;
}

OffscreenTarget::OffscreenTarget(OffscreenTarget&& other) noexcept { *this = std::move(other); }

OffscreenTarget& OffscreenTarget::operator=(OffscreenTarget&& other) noexcept {
  if (this != &other) {
    release();
    framebuffer_ = std::exchange(other.framebuffer_, 0);
    colour_ = std::exchange(other.colour_, 0);
    depth_ = std::exchange(other.depth_, 0);
    width_ = other.width_;
    height_ = other.height_;
  }
  return *this;
}

OffscreenTarget::~OffscreenTarget() { release(); }

void OffscreenTarget::release() {
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (colour_) glDeleteTextures(1, &colour_);
  if (depth_) glDeleteRenderbuffers(1, &depth_);
  framebuffer_ = colour_ = depth_ = 0;
}

void OffscreenTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width_, height_);
}

Image OffscreenTarget::readLinearRgba() const {
  Image image;
  image.width = width_;
  image.height = height_;
  image.channels = 4;
  image.pixels.resize(std::size_t(width_) * std::size_t(height_) * 4);
  std::vector<float> rows(image.pixels.size());
  glNamedFramebufferReadBuffer(framebuffer_, GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, rows.data());
  const std::size_t stride = std::size_t(width_) * 4;
  for (int y = 0; y < height_; ++y) {  // GL's first row is the bottom one
    std::copy_n(rows.begin() + std::ptrdiff_t(std::size_t(height_ - 1 - y) * stride), stride,
                image.pixels.begin() + std::ptrdiff_t(std::size_t(y) * stride));
  }
  return image;
}

Image encodeSrgb(const Image& linear) {
  Image out = linear;
  for (std::size_t i = 0; i < out.pixels.size(); ++i) {
    if (out.channels == 4 && i % 4 == 3) continue;
    const float c = std::clamp(out.pixels[i], 0.0f, 1.0f);
    out.pixels[i] = c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  }
  return out;
}

}  // namespace bake::play
