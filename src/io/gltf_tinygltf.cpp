// tinygltf's implementation, compiled once into thinlight_io with Debian's nlohmann-json. The
// image and file options (TINYGLTF_NO_STB_IMAGE, TINYGLTF_NO_STB_IMAGE_WRITE,
// TINYGLTF_NO_EXTERNAL_IMAGE) are set for the whole target in CMakeLists.txt, so every file sees
// the same declarations; images are decoded by OpenImageIO (gltf_image.cpp), never by stb.
// Warnings are off for this file only: it is third-party code (CMakeLists.txt).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
