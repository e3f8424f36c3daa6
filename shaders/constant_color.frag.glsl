// Writes one colour to every covered pixel: the uniform u_color, or the compile-time constant
// TL_CONSTANT_COLOR (a vec4 expression) when that permutation is defined. Used to clear with
// exact values and by the GL tests.
layout(location = 0) out vec4 o_color;

#ifdef TL_CONSTANT_COLOR
void main() { o_color = TL_CONSTANT_COLOR; }
#else
uniform vec4 u_color;
void main() { o_color = u_color; }
#endif
