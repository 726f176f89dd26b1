# Sources of the Rendering half of the UnstructuredVolume module (included by the root CMakeLists.txt).
# The mappers land here; the GLSL they use is embedded from Shaders/ by the root CMakeLists.txt.
set(uv_rendering_sources)
set(uv_rendering_headers)
set(uv_rendering_private_headers)
