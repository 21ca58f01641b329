#version 450
// A key's drawing (premultiplied alpha, its layer of the artwork array) times a tint, or, for
// layer < 0, a plain premultiplied colour (a view's background).
#extension GL_GOOGLE_include_directive : require
#include "sheet_push.glsl"

layout(set = 0, binding = 0) uniform sampler2DArray artwork;
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;  // premultiplied; blended ONE, ONE_MINUS_SRC_ALPHA

void main() {
  if (sheet.layer < 0) {
    color = sheet.colour;
    return;
  }
  color = texture(artwork, vec3(uv, float(sheet.layer))) * sheet.colour;
}
