#pragma once
// The OSMesa back end of HeadlessContext. This header is free of GL headers on purpose: osmesa.h pulls in
// <GL/gl.h>, which cannot share a translation unit with GLAD's <glad/gl.h>.

#include <memory>
#include <string>

#include "Platform/GlContext.h"

/// An OSMesa context with its own RGBA colour buffer (rows bottom-up, as glReadPixels returns them).
/// Returns nullptr and sets *error if OSMesa refuses the requested format or size.
std::unique_ptr<HeadlessContext> CreateOSMesaContext(int width, int height, std::string* error);
