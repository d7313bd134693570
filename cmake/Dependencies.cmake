# Third-party code comes from the system (Debian packages) or, for sources compiled into
# the wasm build, from Debian source packages unpacked by tools/deps.sh into third_party/.
# Outside Debian, FetchContent downloads the upstream release archives; as usual,
# FETCHCONTENT_SOURCE_DIR_<NAME> points it at a local copy instead.
include(FetchContent)

# Header-only libraries. On the web target the system include dir cannot be used as a
# whole (it holds glibc headers), so the library folders are linked into a private one.
set(PT_SYSINC "${CMAKE_BINARY_DIR}/sysinc")
file(MAKE_DIRECTORY "${PT_SYSINC}")
function(pt_header_lib name probe url)
  if(EXISTS "/usr/include/${name}/${probe}")
    if(NOT EXISTS "${PT_SYSINC}/${name}")
      file(CREATE_LINK "/usr/include/${name}" "${PT_SYSINC}/${name}" SYMBOLIC)
    endif()
  else()
    FetchContent_Declare(${name} URL ${url})
    FetchContent_Populate(${name})
    string(TOLOWER ${name} lname)
    file(CREATE_LINK "${${lname}_SOURCE_DIR}/${name}" "${PT_SYSINC}/${name}" SYMBOLIC)
  endif()
endfunction()
pt_header_lib(glm glm.hpp https://github.com/g-truc/glm/archive/refs/tags/0.9.9.8.tar.gz)
pt_header_lib(stb stb_image.h https://github.com/nothings/stb/archive/5736b15f7ea0ffb08dd38af21067c314d6a3aae9.tar.gz)
pt_header_lib(nlohmann json.hpp https://github.com/nlohmann/json/releases/download/v3.11.2/include.zip)
# Single headers at the top of the include folder (used header-only): tinyobjloader,
# tinygltf (which includes <nlohmann/json.hpp>).
function(pt_single_header file url subdir)
  if(EXISTS "/usr/include/${file}")
    if(NOT EXISTS "${PT_SYSINC}/${file}")
      file(CREATE_LINK "/usr/include/${file}" "${PT_SYSINC}/${file}" SYMBOLIC)
    endif()
  else()
    string(REGEX REPLACE "[^a-z]" "" dep "${file}")
    FetchContent_Declare(${dep} URL ${url})
    FetchContent_Populate(${dep})
    file(CREATE_LINK "${${dep}_SOURCE_DIR}/${subdir}${file}" "${PT_SYSINC}/${file}" SYMBOLIC)
  endif()
endfunction()
pt_single_header(tiny_obj_loader.h https://github.com/tinyobjloader/tinyobjloader/archive/refs/tags/v2.0.0rc10.tar.gz "")
pt_single_header(tiny_gltf.h https://github.com/syoyo/tinygltf/archive/refs/tags/v2.7.0.tar.gz "")
add_library(pt_headers INTERFACE)
target_include_directories(pt_headers SYSTEM INTERFACE "${PT_SYSINC}")
target_compile_definitions(pt_headers INTERFACE GLM_FORCE_XYZW_ONLY)

# A Debian source package unpacked by tools/deps.sh wins over a download.
function(pt_local_source name)
  string(TOUPPER ${name} uname)
  file(GLOB found "${CMAKE_SOURCE_DIR}/third_party/${name}-*")
  if(found AND NOT FETCHCONTENT_SOURCE_DIR_${uname})
    list(GET found 0 dir)
    set(FETCHCONTENT_SOURCE_DIR_${uname} "${dir}" CACHE PATH "" FORCE)
  endif()
endfunction()

# tinyxml2: the system library natively, compiled from source for the web.
if(NOT PT_WEB)
  find_package(tinyxml2 CONFIG QUIET)
endif()
if(TARGET tinyxml2::tinyxml2)
  add_library(pt_tinyxml2 ALIAS tinyxml2::tinyxml2)
else()
  pt_local_source(tinyxml2)
  FetchContent_Declare(tinyxml2 URL https://github.com/leethomason/tinyxml2/archive/refs/tags/9.0.0.tar.gz)
  FetchContent_GetProperties(tinyxml2)
  if(NOT tinyxml2_POPULATED)
    FetchContent_Populate(tinyxml2)
  endif()
  add_library(pt_tinyxml2_src STATIC "${tinyxml2_SOURCE_DIR}/tinyxml2.cpp")
  target_include_directories(pt_tinyxml2_src SYSTEM PUBLIC "${tinyxml2_SOURCE_DIR}")
  add_library(pt_tinyxml2 ALIAS pt_tinyxml2_src)
endif()

# GL: GLES 3 headers everywhere; natively EGL + GLESv2 through libglvnd.
if(NOT PT_WEB)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)
  pkg_check_modules(GLES REQUIRED IMPORTED_TARGET glesv2)
endif()

# Dear ImGui: only the interactive (web) app uses it.
if(PT_WEB)
  pt_local_source(imgui)
  FetchContent_Declare(imgui URL https://github.com/ocornut/imgui/archive/refs/tags/v1.86.tar.gz)
  FetchContent_GetProperties(imgui)
  if(NOT imgui_POPULATED)
    FetchContent_Populate(imgui)
  endif()
  add_library(pt_imgui STATIC
    "${imgui_SOURCE_DIR}/imgui.cpp" "${imgui_SOURCE_DIR}/imgui_draw.cpp"
    "${imgui_SOURCE_DIR}/imgui_tables.cpp" "${imgui_SOURCE_DIR}/imgui_widgets.cpp"
    "${imgui_SOURCE_DIR}/backends/imgui_impl_glfw.cpp"
    "${imgui_SOURCE_DIR}/backends/imgui_impl_opengl3.cpp")
  target_include_directories(pt_imgui SYSTEM PUBLIC "${imgui_SOURCE_DIR}" "${imgui_SOURCE_DIR}/backends")
  target_compile_definitions(pt_imgui PUBLIC IMGUI_IMPL_OPENGL_ES3 IMGUI_DISABLE_OBSOLETE_FUNCTIONS)
endif()
