// The drawing sheet's push constants (std430, 64 bytes); engine/renderers/drawing_sheet.cpp's
// SheetPush matches it.
layout(push_constant) uniform SheetPush {
  vec4 clipRect;  // x0, y0, x1, y1: the rectangle in clip space
  vec4 uvRect;    // u0, v0, u1, v1: the part of the layer it shows (may reach past [0, 1]: clamped)
  vec4 colour;    // premultiplied tint (layer >= 0) or fill (layer < 0)
  int layer;      // the key's layer of the artwork array, or -1 for a plain fill
} sheet;
