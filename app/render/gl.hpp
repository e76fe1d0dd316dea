// The OpenGL 3.3 core API as the renderer sees it: glad's generated loader (one function
// table for the process, filled by GlContext::make_current). Include this, never <GL/gl.h>.
#pragma once

#include <glad/gl.h>
