# ctest mpi_cli_sod (label mpi): `mpirun -np 2 tephra DECK` writes what the
# 1-rank run writes, and restarts across rank counts continue it.
#   DECK: riemann_sm.ups (decks README A8) cut into 4 patches, the diaphragm
#   at x = 0.5 on a patch cut, checkpoints every 40 steps.
#   1. tephra DECK (no mpirun) -> np1;  mpirun -np 2 tephra DECK -> np2.
#      Every .dat file of np1 must equal np2's byte for byte (rank 0 writes
#      the ordered global sums), and `tephra extract --all-times` of
#      rho_CC, press_CC, vel_CC must print the same text (every frame; since
#      session 25 the 2-rank frames are one file per rank plus an index, read
#      through the index; a missing rank file makes extract fail naming it).
#   2. Restart 2 -> 1: a copy of np2 restarted by one process from its
#      checkpoint before the end; 1 -> 2: a copy of np1 restarted by
#      mpirun -np 2; 2 -> 4: a copy of np2 restarted by mpirun -np 4 (one
#      patch per rank). All must end with np1's .dat files and fields.
#   3. Since session 27 the 2-rank checkpoints are per-rank files and a
#      manifest: damaged copies (see below) must fail or fall back cleanly.
# Variables: TEPHRA, MPIEXEC, DECK_IN, WORK.
cmake_minimum_required(VERSION 3.16)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
endfunction()

function(expect_same_output a b what)
  file(GLOB dats RELATIVE ${a} ${a}/*.dat)
  list(LENGTH dats n)
  if(n EQUAL 0)
    message(FATAL_ERROR "${a} has no .dat files")
  endif()
  foreach(d ${dats})
    file(READ ${a}/${d} ta)
    if(NOT EXISTS ${b}/${d})
      message(FATAL_ERROR "${what}: ${b}/${d} missing")
    endif()
    file(READ ${b}/${d} tb)
    if(NOT ta STREQUAL tb)
      message(FATAL_ERROR "${what}: ${d} differs\n--- ${a}\n${ta}\n--- ${b}\n${tb}")
    endif()
  endforeach()
  foreach(var rho_CC press_CC vel_CC)
    execute_process(COMMAND ${TEPHRA} extract ${a} --var ${var} --all-times OUTPUT_VARIABLE ea RESULT_VARIABLE ra)
    execute_process(COMMAND ${TEPHRA} extract ${b} --var ${var} --all-times OUTPUT_VARIABLE eb RESULT_VARIABLE rb)
    if(NOT ra EQUAL 0 OR NOT rb EQUAL 0 OR NOT ea STREQUAL eb OR ea STREQUAL "")
      message(FATAL_ERROR "${what}: extract ${var} differs (exit ${ra}, ${rb})")
    endif()
  endforeach()
  message(STATUS "${what}: ${n} .dat files and rho_CC, press_CC, vel_CC of every frame identical")
endfunction()

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(READ ${DECK_IN} deck)
string(REGEX REPLACE "<patches>[^<]*</patches>" "<patches>[4,1,1]</patches>" deck "${deck}")
string(REGEX REPLACE "<checkpoint[^>]*/>" "<checkpoint timestepInterval=\"40\" cycle=\"2\"/>" deck "${deck}")
file(WRITE ${WORK}/sod4.ups "${deck}")

set(MPI2 ${MPIEXEC} -n 2)
run(${TEPHRA} ${WORK}/sod4.ups --output ${WORK}/np1 --quiet)
run(${MPI2} ${TEPHRA} ${WORK}/sod4.ups --output ${WORK}/np2 --quiet)
expect_same_output(${WORK}/np1 ${WORK}/np2 "1 vs 2 ranks")

# Session 25 (issue 7 item 4): the 2-rank run wrote one frame file per rank
# (frames/t<step>.r<rank>.h5) and an index per frame; the 1-rank run single
# files. A missing rank file: `tephra extract` fails, naming it.
file(GLOB np1_rank_files ${WORK}/np1/frames/t*.r*.h5)
file(GLOB np2_rank0 ${WORK}/np2/frames/t*.r0.h5)
file(GLOB np2_rank1 ${WORK}/np2/frames/t*.r1.h5)
file(GLOB np2_frames ${WORK}/np2/frames/t?????.h5)
list(LENGTH np2_rank0 n0)
list(LENGTH np2_rank1 n1)
list(LENGTH np2_frames nf)
if(np1_rank_files OR n0 EQUAL 0 OR NOT n0 EQUAL n1 OR NOT n0 EQUAL nf)
  message(FATAL_ERROR "rank files: np1 has '${np1_rank_files}', np2 has ${n0} rank-0 and ${n1} rank-1 files for ${nf} frames")
endif()
file(COPY ${WORK}/np2/ DESTINATION ${WORK}/missing)
file(GLOB last_rank1 ${WORK}/missing/frames/t*.r1.h5)
list(SORT last_rank1)
list(GET last_rank1 -1 gone)
file(REMOVE ${gone})
execute_process(COMMAND ${TEPHRA} extract ${WORK}/missing --var press_CC --step last
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
get_filename_component(gone_name ${gone} NAME)
string(FIND "${err}" "${gone_name}" named)
if(rc EQUAL 0 OR named EQUAL -1)
  message(FATAL_ERROR "missing rank file ${gone}: extract exit ${rc}, stderr: ${err}")
endif()
message(STATUS "2 ranks: ${n0} frames of one file per rank; missing ${gone_name}: exit ${rc}: ${err}")

# Session 27 (issue 7 item 4): the 2-rank run wrote each checkpoint as one
# file per rank (checkpoints/c<step>.r<rank>.h5) and a manifest c<step>.h5;
# the 1-rank run single files. A restart from a copy whose newest checkpoint
# lost its rank-1 file, or has it truncated, fails naming the file; without
# the newest manifest (an interrupted write) the restart takes the previous
# checkpoint and still ends with np1's output.
file(GLOB np1_rank_ckpts ${WORK}/np1/checkpoints/c*.r*.h5)
file(GLOB np2_ckpts ${WORK}/np2/checkpoints/c?????.h5)
file(GLOB np2_ckpt_r0 ${WORK}/np2/checkpoints/c*.r0.h5)
file(GLOB np2_ckpt_r1 ${WORK}/np2/checkpoints/c*.r1.h5)
list(LENGTH np2_ckpts nc)
list(LENGTH np2_ckpt_r0 nc0)
list(LENGTH np2_ckpt_r1 nc1)
if(np1_rank_ckpts OR nc LESS 2 OR NOT nc EQUAL nc0 OR NOT nc EQUAL nc1)
  message(FATAL_ERROR "rank checkpoints: np1 has '${np1_rank_ckpts}', np2 has ${nc} manifests, ${nc0} rank-0 and ${nc1} rank-1 files")
endif()
list(SORT np2_ckpt_r1)
list(GET np2_ckpt_r1 -1 newest_r1)
get_filename_component(newest_r1 ${newest_r1} NAME)
foreach(damage missing truncated)
  file(COPY ${WORK}/np2/ DESTINATION ${WORK}/ckpt_${damage})
  if(damage STREQUAL "missing")
    file(REMOVE ${WORK}/ckpt_${damage}/checkpoints/${newest_r1})
  else()
    file(READ ${WORK}/ckpt_${damage}/checkpoints/${newest_r1} head LIMIT 2000 HEX)
    file(WRITE ${WORK}/ckpt_${damage}/checkpoints/${newest_r1} "truncated")
  endif()
  execute_process(COMMAND ${TEPHRA} --restart ${WORK}/ckpt_${damage} --quiet
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(FIND "${err}" "${newest_r1}" named)
  if(rc EQUAL 0 OR named EQUAL -1)
    message(FATAL_ERROR "${damage} rank checkpoint file ${newest_r1}: restart exit ${rc}, stderr: ${err}")
  endif()
  message(STATUS "${damage} ${newest_r1}: restart exit ${rc}: ${err}")
endforeach()
file(COPY ${WORK}/np2/ DESTINATION ${WORK}/no_manifest)
list(SORT np2_ckpts)
list(GET np2_ckpts -1 newest_manifest)
get_filename_component(newest_manifest ${newest_manifest} NAME)
file(REMOVE ${WORK}/no_manifest/checkpoints/${newest_manifest})
run(${TEPHRA} --restart ${WORK}/no_manifest --quiet)
expect_same_output(${WORK}/np1 ${WORK}/no_manifest "2-rank checkpoint without its newest manifest restarted on 1")
file(GLOB orphans ${WORK}/no_manifest/checkpoints/c*.r*.h5)
foreach(f ${orphans})
  get_filename_component(n ${f} NAME)
  if(n STREQUAL newest_r1)
    message(FATAL_ERROR "the manifest-less rank file ${n} survived the restart's next checkpoint")
  endif()
endforeach()

file(COPY ${WORK}/np2/ DESTINATION ${WORK}/restart21)
run(${TEPHRA} --restart ${WORK}/restart21 --quiet)
expect_same_output(${WORK}/np1 ${WORK}/restart21 "checkpoint of 2 ranks restarted on 1")

file(COPY ${WORK}/np1/ DESTINATION ${WORK}/restart12)
run(${MPI2} ${TEPHRA} --restart ${WORK}/restart12 --quiet)
expect_same_output(${WORK}/np1 ${WORK}/restart12 "checkpoint of 1 rank restarted on 2")

# 2 -> 4 (issue 7 item 4): the 2-rank checkpoint continued by 4 ranks
# (oversubscribed on small machines: yield when idle so waiting ranks give up their core).
set(ENV{OMPI_MCA_mpi_yield_when_idle} 1)
set(ENV{OMP_NUM_THREADS} 1)  # unbound oversubscribed ranks would each start a thread per core
file(COPY ${WORK}/np2/ DESTINATION ${WORK}/restart24)
run(${MPIEXEC} -n 4 ${TEPHRA} --restart ${WORK}/restart24 --quiet)
expect_same_output(${WORK}/np1 ${WORK}/restart24 "checkpoint of 2 ranks restarted on 4")
