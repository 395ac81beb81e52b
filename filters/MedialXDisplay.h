/// \file
/// The X connection for offscreen rendering. Debian's VTK renders through GLX only, and its X window
/// aborts the process when its own XOpenDisplay fails; a busy Xvfb refuses about one connection in 40.
/// So Medial opens the connection itself, with retries, and hands it to VTK (SetDisplayId).
#pragma once

namespace medial {

///@{
/// Opens $DISPLAY, retrying over about a second. Returns an X11 Display* as void*, or null when DISPLAY
/// is unset or nothing accepts the connection.
void* openXDisplay();
void closeXDisplay(void* display);
///@}

}  // namespace medial
