# A glTF rendered straight away (no XML): its own materials, the default environment, path
# mode and the framing camera give a finite, non-black mean. bench takes one too. A
# malformed .gltf is one line naming the file and its JSON pointer, exit 1.
file(MAKE_DIRECTORY "${OUT}")
file(REMOVE "${OUT}/grid.pfm")
execute_process(COMMAND ${LAUNCH} "${BIN}" render "${SRC}/assets/gltf/mr-grid.gltf" --spp 2 --size 32x24 --out "${OUT}/grid.pfm"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS "${OUT}/grid.pfm" OR NOT out MATCHES "mode: path")
  message(FATAL_ERROR "rendering the .gltf failed (${rc}): ${out} ${err}")
endif()
if(NOT out MATCHES "mean radiance: ([0-9.e+-]+) ([0-9.e+-]+) ([0-9.e+-]+); non-finite samples: 0,")
  message(FATAL_ERROR "no finite mean: ${out}")
endif()
foreach(c "${CMAKE_MATCH_1}" "${CMAKE_MATCH_2}" "${CMAKE_MATCH_3}")
  if(NOT c GREATER 0.01)
    message(FATAL_ERROR "a black or near-black image (mean ${c}): ${out}")
  endif()
endforeach()
execute_process(COMMAND ${LAUNCH} "${BIN}" bench "${SRC}/assets/gltf/emissive.gltf" --size 16x16 --seconds 0.3 --reference-value 1
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "spp/s")
  message(FATAL_ERROR "bench of a .gltf failed (${rc}): ${out} ${err}")
endif()
file(WRITE "${OUT}/bad.gltf" "{\"asset\":{\"version\":\"2.0\"},\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":5}}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}")
execute_process(COMMAND ${LAUNCH} "${BIN}" render "${OUT}/bad.gltf" --out "${OUT}/never.png"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "^pathtracer: [^\n]*bad.gltf: /meshes/0/primitives/0/attributes/POSITION[^\n]*\n$" OR err MATCHES "<Mesh>")
  message(FATAL_ERROR "unexpected (${rc}): ${err}")
endif()
