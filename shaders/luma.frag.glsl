// Adds gamma-encoded luma in alpha to a caller image, so FXAA can run on it.
in vec2 v_uv;
layout(binding = TL_UNIT_OUTPUT) uniform sampler2D u_image; // the caller's image, uploaded into the output
layout(location = TL_OUT_LDR) out vec4 o_color;

void main()
{
    vec3 c = texelFetch(u_image, ivec2(gl_FragCoord.xy), 0).rgb;
    o_color = vec4(c, dot(c, vec3(0.299, 0.587, 0.114)));
}
