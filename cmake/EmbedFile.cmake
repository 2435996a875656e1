# landsim_embed_file(OUT_CPP INPUT SYMBOL NAMESPACE)
# Generates a .cpp defining `extern const std::string_view <NAMESPACE>::<SYMBOL>` holding the
# bytes of INPUT, so that data (the default scene's elevation grid) ships inside the program.
function(landsim_embed_file out_cpp input symbol ns)
  set(script ${CMAKE_SOURCE_DIR}/cmake/EmbedFileScript.cmake)
  add_custom_command(
    OUTPUT ${out_cpp}
    COMMAND ${CMAKE_COMMAND} -DINPUT=${input} -DOUTPUT=${out_cpp} -DSYMBOL=${symbol}
            -DNAMESPACE=${ns} -P ${script}
    DEPENDS ${input} ${script}
    COMMENT "Embedding ${input}"
    VERBATIM)
endfunction()
