# hair25d model and eval-layering on the command line: usage, bad input, the
# outputs a user asked for, and never a folder of someone else's files lost.
set(case1 ${PROJECT_SOURCE_DIR}/tests/data/annotated/case1)
set(case5 ${PROJECT_SOURCE_DIR}/tests/data/annotated/case5)
set(annotated ${PROJECT_SOURCE_DIR}/tests/data/annotated)
set(hair25d $<TARGET_FILE:hair25d>)

# Automatic regions would make the paper and the face strands too.
hair25d_cli_test(model_needs_to_know_the_hair 2 STDERR "say which regions are hair"
  ARGS model ${case5}/image.png -o model_no_hair)
hair25d_cli_test(model_regions_of_another_size 1 STDERR "regions.png: regions are 640x732.*same size"
  ARGS -q model ${case5}/image.png --regions ${case1}/regions.png -o model_wrong_size)
hair25d_cli_test(model_malformed_strokes 1 STDERR "layering.json"
  ARGS -q model ${case5}/image.png --strokes ${case5}/layering.json -o model_bad_strokes)
hair25d_cli_test(model_bad_hair_colour 1 STDERR "expected #RRGGBB"
  ARGS -q model ${case5}/image.png --hair-colour blue -o model_bad_colour)

add_test(NAME cli.model_keeps_a_folder_of_other_files
  COMMAND bash -c "rm -rf keep && mkdir keep && echo mine > keep/notes.txt
    ${hair25d} -q model ${case5}/image.png --regions ${case5}/regions.png -o keep 2> model_keeps_a_folder_of_other_files.err
    status=$?; cat model_keeps_a_folder_of_other_files.err
    test $status = 1 && grep -q '^hair25d: -o keep: .*notes.txt' model_keeps_a_folder_of_other_files.err &&
      test \"$(cat keep/notes.txt)\" = mine &&
      test ! -e keep/model.json && test -z \"$(ls -A | grep '^\\.keep')\""
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})

# --head is honoured without strokes; "hc/" names the folder hc.
add_test(NAME cli.model_by_hair_colour_with_head
  COMMAND bash -c "rm -rf hc && ${hair25d} -q model ${case5}/image.png --hair-colour '#5a82cc' \
      --colour-tolerance 60 --head 461.5 614.8 -o hc/ &&
    tr -d ' \\n' < hc/model.json | grep -q '\"head_center\":\\[461.5,614.8\\]' &&
    test -s hc/contact_sheet.png && test -s hc/background.png"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})

# A bad --json path fails before any work, and no overlays are left behind.
add_test(NAME cli.eval_layering_json_into_a_folder
  COMMAND bash -c "rm -rf ov_json && mkdir -p json_dir &&
    ${hair25d} -q eval-layering ${annotated} --json json_dir --overlays ov_json 2> eval_layering_json_into_a_folder.err
    status=$?; cat eval_layering_json_into_a_folder.err
    test $status = 1 && grep -q 'is a folder' eval_layering_json_into_a_folder.err && test ! -e ov_json"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME cli.eval_layering_overlays_keep_other_files
  COMMAND bash -c "rm -rf ov_keep && mkdir ov_keep && echo mine > ov_keep/notes.txt
    ${hair25d} -q eval-layering ${annotated} --overlays ov_keep > /dev/null 2> eval_layering_overlays_keep_other_files.err
    status=$?; cat eval_layering_overlays_keep_other_files.err
    test $status = 1 && grep -q '^hair25d: --overlays ov_keep: .*notes.txt' eval_layering_overlays_keep_other_files.err &&
      test \"$(cat ov_keep/notes.txt)\" = mine && test ! -e ov_keep/case0.png"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
# A --json in a folder not made yet is written there; one under a file is
# refused before any case is run.
add_test(NAME cli.eval_layering_json_in_a_new_folder
  COMMAND bash -c "rm -rf new_json && ${hair25d} -q eval-layering ${annotated} --json new_json/a/r.json
      > /dev/null && test -s new_json/a/r.json && echo x > a_file &&
    ! ${hair25d} -q eval-layering ${annotated} --json a_file/r.json 2> eval_layering_json_in_a_new_folder.err &&
    grep -q 'a_file is a file' eval_layering_json_in_a_new_folder.err"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME cli.eval_layering_overlays_written_whole
  COMMAND bash -c "rm -rf ov_whole && ${hair25d} -q eval-layering ${annotated} --overlays ov_whole/
      > /dev/null && test $(ls ov_whole | wc -l) = 6 && test -s ov_whole/case5.png"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})

# Inputs the output would replace: the report over a case's own file, a
# model folder holding its own drawing.
add_test(NAME cli.eval_layering_json_never_over_a_case_file
  COMMAND bash -c "rm -rf cases_copy && mkdir cases_copy && cp -r ${case5} cases_copy/ &&
    cp cases_copy/case5/layering.json before.json
    ! ${hair25d} -q eval-layering cases_copy --json cases_copy/case5/layering.json 2> eval_layering_json_never_over_a_case_file.err &&
    grep -q '^hair25d: --json .*lies in the case folder' eval_layering_json_never_over_a_case_file.err &&
    cmp -s before.json cases_copy/case5/layering.json &&
    ${hair25d} -q eval-layering cases_copy --json cases_copy/report.json > /dev/null &&
    test -s cases_copy/report.json"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME cli.model_never_over_its_input
  COMMAND bash -c "rm -rf own && mkdir own && cp ${case5}/image.png own/ &&
    ! ${hair25d} -q model own/image.png --regions ${case5}/regions.png -o own 2> model_never_over_its_input.err &&
    grep -q '^hair25d: -o own: the input own/image.png lies in it' model_never_over_its_input.err &&
    cmp -s own/image.png ${case5}/image.png && test ! -e own/model.json"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
# An output folder needs a name of its own: "" or "." would replace the
# current folder; refused before any work.
hair25d_cli_test(model_into_the_current_folder 1 STDERR "^hair25d: -o \".\": give the output folder a name"
  ARGS -q model ${case5}/image.png --regions ${case5}/regions.png -o .)
add_test(NAME cli.segment_into_no_folder
  COMMAND bash -c "${hair25d} -q segment ${case5}/image.png --strokes ${case5}/strokes.json \\
      -o '' 2> segment_into_no_folder.err; status=$?; cat segment_into_no_folder.err
    test $status = 1 && grep -q '^hair25d: -o \"\": give the output folder a name' segment_into_no_folder.err"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
# A head centre absurdly far (its squared distances overflowed in the
# skeleton: a crash) is refused before any work, naming --head.
hair25d_cli_test(model_head_far_away 1 STDERR "^hair25d: --head \\(1e\\+200, 100\\): the head centre must lie within"
  ARGS -q model ${case5}/image.png --regions ${case5}/regions.png --head 1e200 100 -o model_far_head)
hair25d_cli_test(model_head_not_a_number 1 STDERR "^hair25d: --head \\(nan, 100\\): the head centre must be finite"
  ARGS -q model ${case5}/image.png --regions ${case5}/regions.png --head nan 100 -o model_nan_head)
hair25d_cli_test(segment_hair_colour_with_signs 1 STDERR "expected #RRGGBB"
  ARGS -q segment ${case5}/image.png --hair-colour "#-1-1-1" -o seg_signs)
hair25d_cli_test(segment_colour_tolerance_nan 1 STDERR "--colour-tolerance: must be a finite number"
  ARGS -q segment ${case5}/image.png --hair-colour "#5a82cc" --colour-tolerance nan -o seg_nan)
hair25d_cli_test(model_colour_tolerance_needs_a_colour 2 STDERR "--colour-tolerance requires --hair-colour"
  ARGS -q model ${case5}/image.png --regions ${case5}/regions.png --colour-tolerance 3 -o model_tol)

# Marked "hair" that is really the paper (a --hair-colour of the paper's own
# colour) is built but called out on stderr; real hair is not.
hair25d_cli_test(model_warns_when_the_hair_is_the_paper 0
  STDERR "^warning: hair region [0-9]+ covers [0-9]+% of the drawing and touches all four of its sides: is it the paper\\? Check --hair-colour #e1f2ec"
  ARGS -q model ${case5}/image.png --hair-colour "#e1f2ec" -o model_paper)
add_test(NAME cli.model_real_hair_gives_no_warning
  COMMAND bash -c "rm -rf model_hair && $<TARGET_FILE:hair25d> -q model ${case5}/image.png --hair-colour '#5a82cc' -o model_hair 2> model_real_hair_gives_no_warning.err; status=$?; cat model_real_hair_gives_no_warning.err; test $status = 0 && ! grep -q warning model_real_hair_gives_no_warning.err"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
