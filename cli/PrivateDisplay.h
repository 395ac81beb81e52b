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
  bool startedXvfb() const { return xvfb_ > 0; }
  // The open X connection (an X11 Display*), for vtkRenderWindow::SetDisplayId: VTK aborts the process
  // when its own XOpenDisplay fails, and under load Xvfb refuses a connection now and then (about one in
  // 40 in a test run), so the connection is opened here, with retries, and handed over.
  void* displayId() const { return display_; }

 private:
  pid_t xvfb_ = -1;
  void* display_ = nullptr;
};

}  // namespace medial::cli
