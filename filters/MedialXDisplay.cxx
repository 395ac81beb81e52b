#include "MedialXDisplay.h"

#include <X11/Xlib.h>

#include <cstdlib>
#include <unistd.h>

namespace medial {

void* openXDisplay() {
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name) return nullptr;
  for (int attempt = 0; attempt < 6; ++attempt) {
    if (Display* display = XOpenDisplay(nullptr)) return display;
    ::usleep(50000u << attempt / 2);
  }
  return nullptr;
}

void closeXDisplay(void* display) {
  if (display) XCloseDisplay(static_cast<Display*>(display));
}

}  // namespace medial
