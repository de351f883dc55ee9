# The web build's dependencies (LIDR_WEB=ON under emcmake): the same Debian packages as the native build, but
# only their headers, and only the header-only ones (glm, nlohmann-json, stb). /usr/include itself cannot be on
# emscripten's include path (glibc's headers would shadow its own libc), so each package's folder is linked
# into a folder of its own and the imported targets the layers already name point there. GL comes from
# emscripten (GLES2/GLES3 headers, WebGL), so GLEW::GLEW is empty here; lidr/base/gl.h picks the headers.
set(LIDR_WEB_INCLUDE ${PROJECT_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${LIDR_WEB_INCLUDE})
foreach(package glm nlohmann stb)
  if(NOT EXISTS /usr/include/${package})
    message(FATAL_ERROR "LIDR_WEB: /usr/include/${package} not found (Debian: libglm-dev, nlohmann-json3-dev, libstb-dev)")
  endif()
  if(NOT EXISTS ${LIDR_WEB_INCLUDE}/${package})
    file(CREATE_LINK /usr/include/${package} ${LIDR_WEB_INCLUDE}/${package} SYMBOLIC)
  endif()
endforeach()

add_library(GLEW::GLEW INTERFACE IMPORTED)
add_library(glm::glm INTERFACE IMPORTED)
set_target_properties(glm::glm PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${LIDR_WEB_INCLUDE})
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
set_target_properties(nlohmann_json::nlohmann_json PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${LIDR_WEB_INCLUDE})
add_library(PkgConfig::STB INTERFACE IMPORTED)
set_target_properties(PkgConfig::STB PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${LIDR_WEB_INCLUDE}/stb)
# The scene importers (scene/io): tinygltf (libtinygltf-dev) and tinyobjloader (libtinyobjloader-dev) are single
# headers; each is linked into web-include on its own (not /usr/include) and tinyobjloader's implementation,
# which Debian ships compiled natively in libtinyobjloader.so, is compiled once into lidr_web like stb_image's.
foreach(header tiny_gltf.h tiny_obj_loader.h)
  if(NOT EXISTS /usr/include/${header})
    message(FATAL_ERROR "LIDR_WEB: /usr/include/${header} not found (Debian: libtinygltf-dev, libtinyobjloader-dev)")
  endif()
  if(NOT EXISTS ${LIDR_WEB_INCLUDE}/${header})
    file(CREATE_LINK /usr/include/${header} ${LIDR_WEB_INCLUDE}/${header} SYMBOLIC)
  endif()
endforeach()
set(TINYGLTF_INCLUDE_DIRS ${LIDR_WEB_INCLUDE})
add_library(tinyobjloader::tinyobjloader INTERFACE IMPORTED)
set_target_properties(tinyobjloader::tinyobjloader PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${LIDR_WEB_INCLUDE})
set(LIDR_WEB_TINYOBJ_SOURCE ${PROJECT_BINARY_DIR}/generated/tinyobjloader_web.cpp)
file(WRITE ${LIDR_WEB_TINYOBJ_SOURCE}
  "#define TINYOBJLOADER_IMPLEMENTATION\n#include <tiny_obj_loader.h>\n")
# Debian's libstb.so holds stb_image's implementation natively; the web build compiles it once into lidr_web.
set(LIDR_WEB_STB_SOURCE ${PROJECT_BINARY_DIR}/generated/stb_image_web.c)
file(WRITE ${LIDR_WEB_STB_SOURCE} "#define STB_IMAGE_IMPLEMENTATION\n#include <stb_image.h>\n")
