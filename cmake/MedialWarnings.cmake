# Warnings for Medial's own targets (not for third-party headers, which are included as SYSTEM).
function(medial_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wno-unused-parameter)
endfunction()
