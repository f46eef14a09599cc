# SPDX-License-Identifier: BSD-3-Clause
# Warnings apply to kinestat's own targets only; third-party headers are SYSTEM includes.
function(kinestat_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion-null)
  if(KINESTAT_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
