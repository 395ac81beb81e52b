// PrivateDisplay: makes sure an X display exists for VTK's offscreen rendering (Debian's VTK is GLX-only
// and aborts without one). When DISPLAY is unset or unreachable, starts a private Xvfb for the lifetime
// of this object, or explains which package is missing.
#pragma once

#include <string>
#include <sys/types.h>

namespace medial::cli {

class PrivateDisplay {
 public:
  PrivateDisplay() = default;
  ~PrivateDisplay();
  PrivateDisplay(const PrivateDisplay&) = delete;
  PrivateDisplay& operator=(const PrivateDisplay&) = delete;

  // True when rendering can go ahead; false with `error` set otherwise.
  bool ensure(std::string& error);
  // The open X connection (an X11 Display*; see filters/MedialXDisplay.h), for vtkMedialScene.
  void* displayId() const { return display_; }

 private:
  pid_t xvfb_ = -1;
  void* display_ = nullptr;
};

}  // namespace medial::cli
