# Runs gcsim plot and gcsim report on small runs; fails with a message naming what went wrong.
# Invoked by CTest as: cmake -DGCSIM=path/to/gcsim -DWORK=scratch/dir -P plot_cli_test.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

function(gcsim expect_status)
  execute_process(COMMAND ${GCSIM} ${ARGN} WORKING_DIRECTORY ${WORK}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL expect_status)
    message(FATAL_ERROR "gcsim ${ARGN}: exit status ${status}, expected ${expect_status}\n${out}\n${err}")
  endif()
  if(err MATCHES "Traceback")
    message(FATAL_ERROR "gcsim ${ARGN} printed a Python traceback:\n${err}")
  endif()
  set(last_out "${out}" PARENT_SCOPE)
  set(last_err "${err}" PARENT_SCOPE)
endfunction()

function(expect_error_mentions)
  foreach(word ${ARGN})
    string(FIND "${last_err}" "${word}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "expected the error to mention '${word}', got:\n${last_err}")
    endif()
  endforeach()
endfunction()

function(expect_png path)
  if(NOT EXISTS ${path})
    message(FATAL_ERROR "${path} was not written")
  endif()
  file(READ ${path} signature LIMIT 8 HEX)
  if(NOT signature STREQUAL "89504e470d0a1a0a")
    message(FATAL_ERROR "${path} is not a PNG (starts with ${signature})")
  endif()
  file(SIZE ${path} size)
  if(size LESS 10000)
    message(FATAL_ERROR "${path} is suspiciously small (${size} bytes)")
  endif()
endfunction()

# A traced run and its four plots.
gcsim(0 bcast --nodes 16 --size 4096 --algo tree --trace t.json --json run.json)
gcsim(0 plot t.json --out plots)
foreach(png gantt mesh_heatmap message_matrix utilization)
  expect_png(${WORK}/plots/${png}.png)
endforeach()

# gcsim paje remakes the Paje file from the CSV (for an interrupted run) exactly as the run wrote it.
gcsim(0 paje t.csv --out again.paje)
file(READ ${WORK}/t.paje written_by_run)
file(READ ${WORK}/again.paje written_again)
if(NOT written_by_run STREQUAL written_again)
  message(FATAL_ERROR "gcsim paje t.csv differs from the t.paje the run wrote")
endif()

# A window and a subset of processors; the CSV names the trace as well as the JSON.
gcsim(0 plot t.csv --out zoom --from-ms 1 --to-ms 8 --procs 0-7,12)
expect_png(${WORK}/zoom/gantt.png)

# A trace without link records (level messages): the heat map routes the messages instead.
gcsim(0 bcast --nodes 8 --size 1024 --algo sequential --trace m.json --trace-level messages)
gcsim(0 plot m.json --out messages --only mesh_heatmap)
expect_png(${WORK}/messages/mesh_heatmap.png)

# The HTML report finds the trace through the run JSON.
gcsim(0 report run.json --out report)
expect_png(${WORK}/report/plots/gantt.png)
file(READ ${WORK}/report/index.html html)
foreach(word "Simulated time next to wall-clock time" "plots/gantt.png" "plots/mesh_heatmap.png")
  string(FIND "${html}" "${word}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "report/index.html does not contain '${word}'")
  endif()
endforeach()

# A rendering run names its image inside its app's settings; the report copies and shows it.
file(READ ${WORK}/run.json run_json)
string(REPLACE "\"nodes\"" "\"radiosity\": {\"scene\": \"CORNELL\", \"image\": \"plots/gantt.png\"}, \"nodes\"" run_json "${run_json}")
file(WRITE ${WORK}/render_run.json "${run_json}")
gcsim(0 report render_run.json --out render_report)
expect_png(${WORK}/render_report/gantt.png)
file(READ ${WORK}/render_report/index.html html)
foreach(word "class=\"image\"" "src=\"gantt.png\"" "radiosity.scene")
  string(FIND "${html}" "${word}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "render_report/index.html does not contain '${word}'")
  endif()
endforeach()

# A sweep that reproduces thesis table 4.3 (CORNELL, sequential broadcast) gets the thesis overlay.
file(WRITE ${WORK}/sweep.csv
"scene,broadcast,nodes,simulated_s,speedup,comm_s,wall_s\n"
"CORNELL,sequential,1,280,1.0,0,10\n"
"CORNELL,sequential,2,230,1.22,20,6\n"
"CORNELL,sequential,4,190,1.47,38,4\n"
"CORNELL,sequential,8,150,1.87,65,3\n")
gcsim(0 plot --sweep sweep.csv --out sweeps)
expect_png(${WORK}/sweeps/sweep_sweep.png)
string(FIND "${last_out}" "overlaid: thesis tables 4.3-4.5 (sequential broadcast), CORNELL" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the sweep of CORNELL with sequential broadcast should overlay thesis tables 4.3-4.5:\n${last_out}")
endif()

# The columns gcsim sweep radiosity writes (thesis cells left empty where the thesis has none) and a
# close variant (comm_s_mean, as gcsim sweep raytrace writes it).
file(WRITE ${WORK}/radiosity.csv
"nodes,simulated_s,speedup,comm_s,wall_s,loops,thesis_s,thesis_speedup,thesis_comm_s\n"
"1,250.5,1.0,0.0,3.2,151,289,1.0000,\n"
"2,210.1,1.19,21.0,2.1,151,236,1.2246,25\n"
"4,170.2,1.47,41.0,1.5,151,180,1.6056,40\n")
gcsim(0 plot --sweep radiosity.csv --out sweeps)
expect_png(${WORK}/sweeps/sweep_radiosity.png)
file(WRITE ${WORK}/raytrace.csv
"nodes,simulated_s,speedup,efficiency,comm_s_mean,compute_s_mean,wall_s\n"
"1,10.0,1.0,1.0,0.0,10.0,5.0\n"
"4,2.7,3.7,0.92,0.2,2.5,5.1\n")
gcsim(0 plot --sweep raytrace.csv --out sweeps)
expect_png(${WORK}/sweeps/sweep_raytrace.png)

# Bad input: one line naming the file and what was expected, no traceback; exit status 3 for a
# file, 2 for an option.
gcsim(3 plot missing.json --out bad)
expect_error_mentions("missing" "does not exist")
file(WRITE ${WORK}/notatrace.csv "hello,world\n1,2\n")
gcsim(3 plot notatrace.csv --out bad)
expect_error_mentions("notatrace.csv" "not a gcsim trace CSV")
gcsim(0 bcast --nodes 4 --size 1024 --trace empty.json --trace-level summary)
gcsim(3 plot empty.json --out bad)
expect_error_mentions("empty.csv" "no records" "--trace-level")
gcsim(2 plot t.json --out bad --procs 0-99)
expect_error_mentions("--procs" "0-15")
gcsim(2 plot t.json --out bad --procs seven)
expect_error_mentions("--procs" "0-7,12")
gcsim(2 plot t.json --out bad --from-ms 500 --to-ms 600)
expect_error_mentions("no records in that window" "spans")
file(WRITE ${WORK}/nocomm.csv "nodes,simulated_s\n1,2\n")
gcsim(3 plot --sweep nocomm.csv --out bad)
expect_error_mentions("nocomm.csv" "missing column comm_s")
gcsim(3 report missing_run.json --out bad)
expect_error_mentions("missing_run.json")
file(WRITE ${WORK}/notrun.json "{\"hello\": 1}")
gcsim(3 report notrun.json --out bad)
expect_error_mentions("notrun.json" "not a gcsim run JSON")
# Malformed CSVs the readers must turn into one error naming the file (not a Python traceback).
file(WRITE ${WORK}/infinite.csv "nodes,simulated_s,comm_s\n1,1e309,1\n")
gcsim(3 plot --sweep infinite.csv --out bad)
expect_error_mentions("infinite.csv" "1e309")
string(REPEAT "x" 200000 huge_field)
file(WRITE ${WORK}/hugefield.csv "nodes,simulated_s,comm_s\n1,\"${huge_field}\",1\n")
gcsim(3 plot --sweep hugefield.csv --out bad)
expect_error_mentions("hugefield.csv:2" "field limit")
file(WRITE ${WORK}/outside.csv "# gcsim trace; level full; 2 processors; mesh 2x1\nkind,proc,peer,start_ps,end_ps,bytes,id,label,thread\ncompute,7,-1,0,10,0,0,x,0\n")
gcsim(3 plot outside.csv --out bad)
expect_error_mentions("outside.csv:3" "processors 0-1")
# Not a regular file: refused before the script would block or read without end.
gcsim(3 plot --sweep /dev/zero --out bad)
expect_error_mentions("/dev/zero" "device")
gcsim(3 report /dev/zero --out bad)
expect_error_mentions("/dev/zero" "device")
file(WRITE ${WORK}/overflow.json "{\"simulated\": {\"s\": 1e309}, \"wall\": 1}")
gcsim(3 report overflow.json --out bad)
expect_error_mentions("overflow.json" "1e309")
gcsim(3 paje missing_trace.csv)
expect_error_mentions("missing_trace.csv" "does not exist")
# An interpreter that fails without a word: gcsim says so (status 1), never a silent exit.
set(ENV{GCSIM_PYTHON} /bin/false)
gcsim(1 plot --sweep nocomm.csv --out bad)
expect_error_mentions("no message" "GCSIM_PYTHON")
unset(ENV{GCSIM_PYTHON})
message(STATUS "gcsim plot and gcsim report: all checks passed")
