# Audit fixes (session 8): empty option values refused (not taken for "not
# given"), CASES_DIR named when missing or a file, numbers too large for a
# double named, the generator's -o handled as every other output folder, and
# the eval-layering overlays drawn larger with a caption band.
set(annotated ${PROJECT_SOURCE_DIR}/tests/data/annotated)
set(case5 ${annotated}/case5)

# An empty value cannot pass through a CMake list: these run through bash.
function(empty_value_test name stderr)
  list(JOIN ARGN " " args)
  add_test(NAME cli.${name}
    COMMAND bash -c "bash ${CMAKE_CURRENT_SOURCE_DIR}/expect.sh 1 --stderr '${stderr}' -- $<TARGET_FILE:hair25d> ${args} && test ! -e never"
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endfunction()
empty_value_test(eval_layering_json_empty "^hair25d: --json \"\": give the report a file name"
  -q eval-layering ${annotated} --json \"\")
empty_value_test(eval_layering_overlays_empty "^hair25d: --overlays \"\": give the output folder a name"
  -q eval-layering ${annotated} --overlays \"\")
hair25d_cli_test(eval_layering_cases_missing 1 STDERR "^hair25d: no_such_cases: no such folder"
  ARGS -q eval-layering no_such_cases)
hair25d_cli_test(eval_layering_open_order_nan 1
  STDERR "^hair25d: --open-order-log-odds: layering::Options::open_order_log_odds = nan; must be finite, or -infinity \\(off\\)$"
  ARGS -q eval-layering ${annotated} --open-order-log-odds nan)
hair25d_cli_test(eval_layering_cases_is_a_file 1 STDERR "image.png: is a file; CASES_DIR must be a folder"
  ARGS -q eval-layering ${case5}/image.png)
empty_value_test(segment_empty_strokes_value
  "^hair25d: --strokes: \"\": give the strokes file.s name \\(the value is empty\\)$"
  -q segment ${case5}/image.png --strokes \"\" -o never)
empty_value_test(model_empty_regions_value "^hair25d: --regions: \"\": give the region map"
  -q model ${case5}/image.png --regions \"\" -o never)
hair25d_cli_test(colour_tolerance_beyond_double 1
  STDERR "^hair25d: --colour-tolerance: must be a number from 0 to 442, not 1e999$"
  ARGS segment ${case5}/image.png --hair-colour "#000000" --colour-tolerance 1e999 -o never)

# case5 (896 x 1162) overlay: drawn 1200 px tall plus its caption band.
add_test(NAME cli.eval_layering_overlay_scaled_with_caption
  COMMAND bash -c "rm -rf ovl_caption && mkdir -p ovl_caption_cases && rm -rf ovl_caption_cases/case5 && cp -r ${case5} ovl_caption_cases/ &&
    $<TARGET_FILE:hair25d> -q eval-layering ovl_caption_cases --overlays ovl_caption > /dev/null &&
    h=$(od -An -tu1 -j20 -N4 ovl_caption/case5.png | awk '{print $1*16777216+$2*65536+$3*256+$4}') &&
    echo height $h && test $h -gt 1240"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})

if(TARGET hair25d-generate)
  set(gen "$<TARGET_FILE:hair25d-generate> --width 96 --height 80 --strands 2 --line-width 2")
  # A folder of other files is left as it was; a file at -o is named; "." refused.
  add_test(NAME cli.generate_keeps_other_folders
    COMMAND bash -c "rm -rf gen_other && mkdir gen_other && echo mine > gen_other/notes.txt &&
      { ${gen} -o gen_other > /dev/null 2> gen_other.err; test $? = 1; } && cat gen_other.err &&
      grep -q '^hair25d-generate: -o gen_other: .*notes.txt' gen_other.err && test ! -e gen_other/case000 &&
      test \"$(cat gen_other/notes.txt)\" = mine &&
      { ${gen} -o gen_other/notes.txt > /dev/null 2> gen_file.err; test $? = 1; } &&
      grep -q 'notes.txt: exists and is not a folder' gen_file.err &&
      { ${gen} -o . > /dev/null 2> gen_dot.err; test $? = 1; } && grep -q 'a name of its own' gen_dot.err"
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  # A second, smaller run replaces the whole set: no stale case002.
  add_test(NAME cli.generate_rerun_replaces_the_set
    COMMAND bash -c "rm -rf gen_rerun && ${gen} --count 3 -o gen_rerun > /dev/null && test -d gen_rerun/case002 &&
      ${gen} --count 1 --seed 5 -o gen_rerun > /dev/null && test -s gen_rerun/case000/image.png &&
      test ! -e gen_rerun/case001 && test ! -e gen_rerun/case002 && test -z \"$(ls -A | grep '^\\.gen_rerun')\""
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endif()

# A folder the system will not let us make beside: the message names the path
# it refused (for /proc the kernel says "No such file or directory", which
# alone reads as if the target were missing).
hair25d_cli_test(segment_output_in_proc 1
  STDERR "^hair25d: /proc/hair25d_out: cannot write the folder \\(at /proc/[^)]+\\): "
  ARGS -q segment ${case5}/image.png --strokes ${case5}/strokes.json -o /proc/hair25d_out)
