# Audit fixes on the command line: writing through links and to standard
# output, a bad case found before any is scored, -q after the command, unknown
# commands named, defaults shown in --help.
set(annotated ${PROJECT_SOURCE_DIR}/tests/data/annotated)
set(hair25d $<TARGET_FILE:hair25d>)

# --json - is standard output: the JSON report only, no table after it.
add_test(NAME cli.eval_layering_json_to_stdout
  COMMAND bash -c "${hair25d} -q eval-layering ${annotated} --json - > json_stdout.out &&
    python3 -c 'import json,sys; d=json.load(open(\"json_stdout.out\")); sys.exit(0 if len(d[\"cases\"]) == 6 else 1)'"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})

# --json and --overlays through links: the links stay, their targets are
# written; /dev/stdout to a pipe gets the JSON and the table.
add_test(NAME cli.eval_layering_writes_through_links
  COMMAND bash -c "rm -rf links && mkdir links && cd links && touch real.json && ln -s real.json link.json &&
    mkdir ovl && ln -s ovl ovl_link &&
    ${hair25d} -q eval-layering ${annotated} --json link.json --overlays ovl_link > /dev/null &&
    test -L link.json && test -s real.json && test -L ovl_link && test -s ovl/case0.png &&
    ${hair25d} -q eval-layering ${annotated} --json /dev/stdout | cat > both.out &&
    grep -q '\"cases\"' both.out && grep -q '^total' both.out && test -z \"$(ls -A | grep tmp)\""
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})

# A truncated layering.json in the last case: refused before any case is
# scored (no progress line), the message naming the file.
add_test(NAME cli.eval_layering_checks_every_case_first
  COMMAND bash -c "rm -rf bad_cases && mkdir bad_cases && cp -r ${annotated}/case0 bad_cases/a &&
    cp -r ${annotated}/case1 bad_cases/b && head -c 100 ${annotated}/case1/layering.json > bad_cases/b/layering.json &&
    ${hair25d} eval-layering bad_cases > bad_cases.out 2> bad_cases.err; status=$?; cat bad_cases.err;
    test $status = 1 && grep -q 'b/layering.json' bad_cases.err && ! grep -q 'eval-layering:' bad_cases.err &&
    test ! -s bad_cases.out"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
