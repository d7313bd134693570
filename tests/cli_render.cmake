file(MAKE_DIRECTORY "${OUT}")
foreach(ext png hdr pfm)
  file(REMOVE "${OUT}/scene0.${ext}")
  execute_process(COMMAND ${LAUNCH} "${BIN}" render "${SRC}/scenes/reference/scene0.xml" --spp 2 --size 32x24 --out "${OUT}/scene0.${ext}"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS "${OUT}/scene0.${ext}")
    message(FATAL_ERROR "render to ${ext} failed (${rc}): ${out} ${err}")
  endif()
  foreach(expect "GL: " "spp/s" "mean radiance: " "wrote ")
    if(NOT out MATCHES "${expect}")
      message(FATAL_ERROR "output lacks '${expect}': ${out}")
    endif()
  endforeach()
endforeach()
file(READ "${OUT}/scene0.png" png LIMIT 8 HEX)
file(READ "${OUT}/scene0.hdr" hdr LIMIT 10)
file(READ "${OUT}/scene0.pfm" pfm LIMIT 3)
if(NOT pfm STREQUAL "PF\n")
  message(FATAL_ERROR "bad pfm signature")
endif()
if(NOT png STREQUAL "89504e470d0a1a0a" OR NOT hdr MATCHES "^#\\?RADIANCE")
  message(FATAL_ERROR "bad file signatures: ${png} / ${hdr}")
endif()
# A scene's <Render> sets what no flag sets; a flag wins.
file(WRITE "${OUT}/render-settings.xml" "<SceneLevel><Camera position=\"0 1 5\"/>
<Render bounces=\"4\" mode=\"whitted\" samples=\"3\"/>
<Objects><Sphere center=\"0 1 0\" radius=\"1\"><Reflect/></Sphere></Objects></SceneLevel>")
execute_process(COMMAND ${LAUNCH} "${BIN}" render "${OUT}/render-settings.xml" --size 16x16 --out "${OUT}/rs.png"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "mode: whitted" OR NOT out MATCHES "rendered 3 spp at 16x16, 4 bounces")
  message(FATAL_ERROR "<Render> not applied (${rc}): ${out} ${err}")
endif()
execute_process(COMMAND ${LAUNCH} "${BIN}" render "${OUT}/render-settings.xml" --size 16x16 --spp 5 --mode path --bounces 7 --out "${OUT}/rs.png"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "mode: path" OR NOT out MATCHES "rendered 5 spp at 16x16, 7 bounces")
  message(FATAL_ERROR "flags did not win over <Render> (${rc}): ${out} ${err}")
endif()
# The error estimate: printed at the end; --target-relmse stops once it is reached (the
# closed room's error halves with the samples: a loose target stops long before --spp).
execute_process(COMMAND ${LAUNCH} "${BIN}" render "${SRC}/scenes/analytic/closed-room.xml" --size 24x24 --spp 4096 --target-relmse 0.004 --out "${OUT}/target.pfm"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "target relMSE 0.004 reached" OR NOT out MATCHES "estimated relMSE: [0-9.e-]+ " OR out MATCHES "rendered 4096 spp")
  message(FATAL_ERROR "--target-relmse did not stop the render (${rc}): ${out} ${err}")
endif()
string(REGEX MATCH "estimated relMSE: ([0-9.e-]+)" _ "${out}")
if(NOT CMAKE_MATCH_1 LESS_EQUAL 0.004)
  message(FATAL_ERROR "stopped above the target: ${CMAKE_MATCH_1}")
endif()
execute_process(COMMAND ${LAUNCH} "${BIN}" render "${SRC}/scenes/analytic/closed-room.xml" --size 8x8 --spp 1 --out "${OUT}/one.pfm"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "estimated relMSE: unknown")
  message(FATAL_ERROR "1 spp must say the estimate is unknown (${rc}): ${out} ${err}")
endif()
