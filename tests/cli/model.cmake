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
    ${hair25d} -q model ${case5}/image.png --regions ${case5}/regions.png -o keep 2> err.txt
    status=$?; cat err.txt
    test $status = 1 && grep -q '^hair25d: -o keep: .*notes.txt' err.txt &&
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
    ${hair25d} -q eval-layering ${annotated} --json json_dir --overlays ov_json 2> err.txt
    status=$?; cat err.txt
    test $status = 1 && grep -q 'is a folder' err.txt && test ! -e ov_json"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME cli.eval_layering_overlays_keep_other_files
  COMMAND bash -c "rm -rf ov_keep && mkdir ov_keep && echo mine > ov_keep/notes.txt
    ${hair25d} -q eval-layering ${annotated} --overlays ov_keep > /dev/null 2> err.txt
    status=$?; cat err.txt
    test $status = 1 && grep -q '^hair25d: --overlays ov_keep: .*notes.txt' err.txt &&
      test \"$(cat ov_keep/notes.txt)\" = mine && test ! -e ov_keep/case0.png"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
# A --json in a folder not made yet is written there; one under a file is
# refused before any case is run.
add_test(NAME cli.eval_layering_json_in_a_new_folder
  COMMAND bash -c "rm -rf new_json && ${hair25d} -q eval-layering ${annotated} --json new_json/a/r.json
      > /dev/null && test -s new_json/a/r.json && echo x > a_file &&
    ! ${hair25d} -q eval-layering ${annotated} --json a_file/r.json 2> err.txt &&
    grep -q 'a_file is a file' err.txt"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME cli.eval_layering_overlays_written_whole
  COMMAND bash -c "rm -rf ov_whole && ${hair25d} -q eval-layering ${annotated} --overlays ov_whole/
      > /dev/null && test $(ls ov_whole | wc -l) = 6 && test -s ov_whole/case5.png"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
