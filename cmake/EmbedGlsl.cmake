# Turns every GLSL file into an entry of a C++ table at build time, keyed by the name
# that #include uses: "rng.glsl" for shaders/rng.glsl, "shapes/sphere.glsl" for src/shapes/.
function(pt_embed_glsl out_var)
  file(GLOB_RECURSE skeleton CONFIGURE_DEPENDS "${CMAKE_SOURCE_DIR}/shaders/*.glsl")
  file(GLOB_RECURSE snippets CONFIGURE_DEPENDS "${CMAKE_SOURCE_DIR}/src/*.glsl")
  set(entries "")
  foreach(f IN LISTS skeleton)
    file(RELATIVE_PATH key "${CMAKE_SOURCE_DIR}/shaders" "${f}")
    list(APPEND entries "${key}=${f}")
  endforeach()
  foreach(f IN LISTS snippets)
    file(RELATIVE_PATH key "${CMAKE_SOURCE_DIR}/src" "${f}")
    list(APPEND entries "${key}=${f}")
  endforeach()
  # Tables computed at build time, never typed in: the glTF sheen lobe's albedo (tools/gen_sheen_lut.py),
  # the GGX lobe's (tools/gen_ggx_ms_lut.py).
  # Each writes its GLSL (a uniform block and its accessors) and the numbers as a C++
  # initialiser (.inc) that render/uniform_tables.cpp uploads into that block.
  set(sheen_lut "${CMAKE_BINARY_DIR}/generated/materials/gltf_sheen_lut.glsl")
  set(sheen_inc "${CMAKE_BINARY_DIR}/generated/materials/gltf_sheen_lut.inc")
  file(MAKE_DIRECTORY "${CMAKE_BINARY_DIR}/generated/materials")
  add_custom_command(OUTPUT "${sheen_lut}" "${sheen_inc}"
    COMMAND python3 "${CMAKE_SOURCE_DIR}/tools/gen_sheen_lut.py" "${sheen_lut}" "${sheen_inc}"
    DEPENDS "${CMAKE_SOURCE_DIR}/tools/gen_sheen_lut.py" "${CMAKE_SOURCE_DIR}/tools/lut_common.py"
    COMMENT "Tabulating the sheen albedo" VERBATIM)
  list(APPEND entries "materials/gltf_sheen_lut.glsl=${sheen_lut}")
  # The GGX lobe's albedos for the multiple-scattering compensation (tools/gen_ggx_ms_lut.py).
  set(ms_lut "${CMAKE_BINARY_DIR}/generated/materials/gltf_ms_lut.glsl")
  set(ms_inc "${CMAKE_BINARY_DIR}/generated/materials/gltf_ms_lut.inc")
  add_custom_command(OUTPUT "${ms_lut}" "${ms_inc}"
    COMMAND python3 "${CMAKE_SOURCE_DIR}/tools/gen_ggx_ms_lut.py" "${ms_lut}" "${ms_inc}"
    DEPENDS "${CMAKE_SOURCE_DIR}/tools/gen_ggx_ms_lut.py" "${CMAKE_SOURCE_DIR}/tools/lut_common.py"
    COMMENT "Tabulating the GGX albedo" VERBATIM)
  list(APPEND entries "materials/gltf_ms_lut.glsl=${ms_lut}")
  set(out "${CMAKE_BINARY_DIR}/generated/embedded_glsl.cpp")
  add_custom_command(OUTPUT "${out}"
    COMMAND ${CMAKE_COMMAND} "-DOUT=${out}" "-DENTRIES=${entries}" -P "${CMAKE_SOURCE_DIR}/cmake/EmbedGlslScript.cmake"
    DEPENDS ${skeleton} ${snippets} "${sheen_lut}" "${ms_lut}" "${CMAKE_SOURCE_DIR}/cmake/EmbedGlslScript.cmake"
    COMMENT "Embedding GLSL sources" VERBATIM)
  set(${out_var} "${out}" PARENT_SCOPE)
  set(PT_TABLE_INCS "${sheen_inc}" "${ms_inc}" PARENT_SCOPE)  # (render/uniform_tables.cpp includes them)
endfunction()
