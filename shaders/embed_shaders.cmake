# Writes OUTPUT: a C++ file defining skinlayer::shader_source(name) over the comma-separated FILES in SOURCE_DIR.
# Each file becomes a raw string literal; the delimiter is checked not to occur in the text.
set(body "// Generated from shaders/ by embed_shaders.cmake. Do not edit.\n#include <stdexcept>\n#include <string>\n#include <string_view>\n\nnamespace skinlayer {\n\nstd::string_view shader_source(std::string_view name) {\n")
string(REPLACE "," ";" FILES "${FILES}")
foreach(file ${FILES})
  file(READ ${SOURCE_DIR}/${file} text)
  string(FIND "${text}" ")skinlayer_glsl\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${file} contains the raw-string delimiter")
  endif()
  string(APPEND body "  if (name == \"${file}\") return R\"skinlayer_glsl(${text})skinlayer_glsl\";\n")
endforeach()
string(APPEND body "  throw std::invalid_argument(\"no shader named \" + std::string(name));\n}\n\n}  // namespace skinlayer\n")
file(WRITE ${OUTPUT} "${body}")
