// The OpenGL 3.3 core API as plain prototypes. The renderer calls gl* directly and links no GL library itself:
// the executable that links it decides (libOSMesa for headless rendering and tests, libGL for the window), so the
// same renderer code runs under both (docs/platform-notes.md). Never link both into one executable.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
