#pragma once
// `amrstream view` in a window (GLFW): traces grow a few steps a frame and render as tubes, with
// the controls of view_panel.hpp, until the window closes or --frames frames have been shown.

#include "amrstream/viewer.hpp"
#include "viewer/view_session.hpp"

namespace amrstream::viewer {

// Throws InputError for the CPU backend: the viewer needs a Vulkan device.
void requireViewerBackend(const BackendRequest& backend);

void runViewWindow(const ViewJob& options, const Reporter& reporter);

}  // namespace amrstream::viewer
