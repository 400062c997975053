# Script mode (ctest): `tetcut_quality_sweeps --gate` writes an entry for every tool size and the
# pooled counts, and the entry of the tool it ran has every field bench/budgets.json gates on, so
# that ci/bench's tool-size figures cannot go missing unnoticed. One sweep of the sphere at one
# median edge.
execute_process(COMMAND ${SWEEPS} --gate ${OUT} --sweeps 1 --only sphere --tool 1x
                RESULT_VARIABLE status OUTPUT_QUIET)
if(status GREATER 1)
  message(FATAL_ERROR "tetcut_quality_sweeps --gate failed (exit ${status})")
endif()
execute_process(COMMAND ${PYTHON} -c "
import json, sys
budgets = json.load(open(sys.argv[1]))
entries = {b['name']: b for b in json.load(open(sys.argv[2]))['benchmarks']}
figures = [f for f in budgets['figures'] if f['benchmark'].startswith('tool_sizes/')]
problems = [] if figures else ['bench/budgets.json gates no tool_sizes figure']
for f in figures:
    if f['benchmark'] not in entries:
        problems.append(f['name'] + ': no entry ' + f['benchmark'])
    elif f['benchmark'] in ('tool_sizes/1x', 'tool_sizes/all') and f['field'] not in entries[f['benchmark']]:
        problems.append(f['name'] + ': ' + f['benchmark'] + ' has no ' + f['field'])
print('\\n'.join(problems) or str(len(figures)) + ' tool-size figures found')
sys.exit(1 if problems else 0)
" ${BUDGETS} ${OUT} RESULT_VARIABLE checked)
if(NOT checked EQUAL 0)
  message(FATAL_ERROR "the tool-size gate's output lacks figures the budgets read")
endif()
