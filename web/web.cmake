# The web target: the interactive app in a WebGL 2 canvas. Included by src/CMakeLists.txt
# when building with Emscripten. Outputs pathtracer.js/.wasm/.data next to our own HTML
# shell (Debian's emcc cannot minify HTML, so it never writes the page itself).

add_executable(pathtracer_web
  "${CMAKE_SOURCE_DIR}/src/app/app.cpp" "${CMAKE_SOURCE_DIR}/src/app/app_loading.cpp" "${CMAKE_SOURCE_DIR}/src/app/app_panel.cpp" "${CMAKE_SOURCE_DIR}/src/app/app_stats.cpp"
  "${CMAKE_SOURCE_DIR}/src/app/env_panel.cpp"
  "${CMAKE_SOURCE_DIR}/src/app/app_interaction.cpp"
  "${CMAKE_SOURCE_DIR}/src/platform/web.cpp"
  "${CMAKE_SOURCE_DIR}/src/platform/web_context.cpp"  # the WebGL context: renderer name, loss, extensions
  "${CMAKE_SOURCE_DIR}/src/platform/web_imgui.cpp"
  "${CMAKE_SOURCE_DIR}/src/platform/web_touch.cpp"  # touches: to ImGui or to the gesture recogniser
  "${CMAKE_SOURCE_DIR}/src/platform/web_hooks.cpp")  # the functions the page calls (PT_EXPORTS below)
set_target_properties(pathtracer_web PROPERTIES OUTPUT_NAME pathtracer SUFFIX ".js")
target_link_libraries(pathtracer_web PRIVATE pt_core pt_imgui)
target_compile_options(pathtracer_web PRIVATE ${PT_WARNINGS})

set(PT_WEB_SHELL_FILES index.html style.css files.js)
set(PT_EXPORTS _main _malloc _free _pt_stats_json _pt_view_query _pt_set_size _pt_set_sample_limit _pt_set_denoise _pt_time_denoise _pt_radiance _pt_display _pt_load_scene _pt_reload_scene _pt_work _pt_load_status _pt_scene_files _pt_scene_list _pt_touch _pt_ui_json)
list(JOIN PT_EXPORTS "," PT_EXPORTS_CSV)
target_link_options(pathtracer_web PRIVATE
  -sUSE_GLFW=3 -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2
  -sALLOW_MEMORY_GROWTH=1
  -sEXPORTED_FUNCTIONS=${PT_EXPORTS_CSV}
  -sEXPORTED_RUNTIME_METHODS=UTF8ToString,stringToUTF8,lengthBytesUTF8,FS,addRunDependency,removeRunDependency
  # SHELL: keeps the repeated --preload-file (CMake de-duplicates plain options).
  "SHELL:--preload-file ${CMAKE_SOURCE_DIR}/scenes@/scenes"
  "SHELL:--preload-file ${CMAKE_SOURCE_DIR}/assets@/assets")  # meshes, image maps, environments

# Debian's emcc runs its JavaScript optimizer with node, which finds acorn and friends only
# through NODE_PATH: set it for the link step so a plain `cmake --build` works.
if(EXISTS /usr/share/nodejs/acorn)
  set_property(TARGET pathtracer_web PROPERTY RULE_LAUNCH_LINK "${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs")
endif()

# Re-link when a scene changes (the .data package is written by the link step).
file(GLOB_RECURSE PT_WEB_SCENES CONFIGURE_DEPENDS "${CMAKE_SOURCE_DIR}/scenes/*" "${CMAKE_SOURCE_DIR}/assets/*")
set_property(TARGET pathtracer_web APPEND PROPERTY LINK_DEPENDS ${PT_WEB_SCENES})

# The HTML shell and styles are copied as they are, on every build.
foreach(f ${PT_WEB_SHELL_FILES})
  add_custom_command(OUTPUT "${CMAKE_BINARY_DIR}/${f}"
    COMMAND ${CMAKE_COMMAND} -E copy_if_different "${CMAKE_SOURCE_DIR}/web/${f}" "${CMAKE_BINARY_DIR}/${f}"
    DEPENDS "${CMAKE_SOURCE_DIR}/web/${f}")
  list(APPEND PT_WEB_SHELL_OUT "${CMAKE_BINARY_DIR}/${f}")
endforeach()
add_custom_target(pathtracer_web_shell ALL DEPENDS ${PT_WEB_SHELL_OUT})
add_dependencies(pathtracer_web pathtracer_web_shell)

# scenes/ and assets/ beside the page as plain files too: the page fetches a scene and the
# files it references over HTTP (web/files.js), so build/web is a complete static site
# (tools/site.sh copies it for GitHub Pages; the dev server serves the source tree instead).
add_custom_target(pathtracer_web_files ALL
  COMMAND ${CMAKE_COMMAND} -E copy_directory "${CMAKE_SOURCE_DIR}/scenes" "${CMAKE_BINARY_DIR}/scenes"
  COMMAND ${CMAKE_COMMAND} -E copy_directory "${CMAKE_SOURCE_DIR}/assets" "${CMAKE_BINARY_DIR}/assets"
  COMMENT "Copying scenes/ and assets/ beside the page")
