// `bakeplay view`: the scene in a GLFW window. Drag with the left button to orbit, scroll to zoom,
// drag with the right button (or use the arrow keys) to move the light, R to reset, Esc to quit. The
// title shows the frame time. The frame is rendered exactly as `render` does (offscreen, linear) and
// presented with the same sRGB encoding. --screenshot writes the window's picture after --frames
// frames and exits (for tests under Xvfb).
#pragma once

#include <string>

#include "bake/core/diagnostics.h"
#include "bake/core/status.h"
#include "play/render.h"

namespace bake::play {

struct WindowSettings {
  ViewSettings view;
  std::string screenshot;  // .png; with it, the window closes itself after `frames` frames
  int frames = 10;
};

Status runView(const WindowSettings& settings, Diagnostics& diagnostics);

}  // namespace bake::play
