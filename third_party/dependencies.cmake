# CMake glue for the system packages the project uses (Debian 12). No sources are copied into the repo:
# every library comes from its Debian package (installed by ../setup.sh). Included from the top-level
# CMakeLists.txt so that the imported targets are visible everywhere.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
# Material files (app/material): JSON through nlohmann-json (nlohmann-json3-dev); pictures that carry their
# material as PNG text chunks through libpng (libpng-dev).
find_package(nlohmann_json 3.11 REQUIRED)
find_package(PNG REQUIRED)
# Environment maps (.hdr) through stb_image (libstb-dev), which the GL-free fuzz targets read too.
find_package(PkgConfig REQUIRED)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
# The GL side's vectors and matrices (glm::glm, libglm-dev): the environment's directions and rotation, the light.
# Header-only, GLSL's types on the CPU; the environment maps, built without the app too, use it.
find_package(glm 0.9.9 REQUIRED CONFIG)

# Previewer and headless rendering (see docs/platform-notes.md): not looked for without the app.
if(NOT SKINLAYER_BUILD_APP)
  return()
endif()
# The OpenPBR export writes MaterialX through pugixml (libpugixml-dev), and its test reads the node definition with it.
find_package(pugixml 1.13 REQUIRED CONFIG)
find_package(glfw3 3.3 REQUIRED)
find_package(OpenGL REQUIRED)
pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)

# The Python package (app/python) and its tests: pybind11 (pybind11-dev), numpy and pytest (python3-numpy,
# python3-pytest). The interpreter is Debian's /usr/bin/python3 unless Python3_EXECUTABLE says otherwise: setup.sh
# installs numpy and pytest for that one, and a python3 earlier on PATH (pyenv, a virtual environment) may have
# neither.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python interpreter of the skinlayer package")
endif()
find_package(Python3 3.9 REQUIRED COMPONENTS Interpreter Development.Module)
find_package(pybind11 2.10 REQUIRED CONFIG)

# Dear ImGui's GLFW and OpenGL3 backends, compiled from the sources that libimgui-dev ships (the prebuilt ones in
# libimgui.a cannot load GL under OSMesa). They call gl* directly through <GL/glcorearb.h> prototypes and link no
# GL library, so the executable decides: libGL for the window.
set(SKINLAYER_IMGUI_BACKENDS "/usr/share/doc/libimgui-dev/examples/backends" CACHE PATH "ImGui backend sources")
add_library(skinlayer_imgui_backends STATIC
  ${SKINLAYER_IMGUI_BACKENDS}/imgui_impl_glfw.cpp
  ${SKINLAYER_IMGUI_BACKENDS}/imgui_impl_opengl3.cpp)
# The backends' headers are packaged apart from their sources, in <includedir>/backends.
target_include_directories(skinlayer_imgui_backends PUBLIC ${SKINLAYER_IMGUI_BACKENDS} ${IMGUI_INCLUDEDIR}/backends)
target_compile_definitions(skinlayer_imgui_backends PUBLIC IMGUI_IMPL_OPENGL_LOADER_CUSTOM GL_GLEXT_PROTOTYPES)
target_compile_options(skinlayer_imgui_backends PRIVATE -include GL/glcorearb.h -w)
target_link_libraries(skinlayer_imgui_backends PUBLIC PkgConfig::IMGUI glfw)
