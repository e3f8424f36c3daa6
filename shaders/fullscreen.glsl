// Full-screen triangle from gl_VertexID, no vertex buffer: vertices 0, 1, 2 cover clip space
// [-1,1]^2 with one triangle (no diagonal seam, no helper-pixel waste along it).
vec2 tl_fullscreen_position(int vertex_id)
{
    return vec2(float((vertex_id & 1) << 2) - 1.0, float((vertex_id & 2) << 1) - 1.0);
}
