# ctest mpi_cli_mpm and mpi_cli_mpmice (label mpi): `mpirun -np 2 tephra
# DECK` for an MPM or MPMICE deck gives the 1-rank answer to round-off, and
# restarts across rank counts continue it.
#   DECK: disks.ups (decks README A1) cut into patches [2,1,1] (the cut at
#   x = 0.5 is crossed by the disks' particles), gimp, checkpoints every 0.7 s (the last at t = 2.8, so a restart runs the last ~0.2 s).
#   1. tephra DECK -> np1; mpirun -np 2 tephra DECK -> np2.
#   2. Restart 2 -> 1 (a copy of np2 by one process), 1 -> 2 (a copy of
#      np1 by mpirun -np 2) and 2 -> 4 (a copy of np2 by mpirun -np 4: for
#      disks two of the four ranks own no patch, for massX one patch each)
#      from the checkpoint before the end.
#   Every .dat file and `tephra extract --step last` of p.x, p.velocity,
#   p.stress must agree: |a - b| <= 1e-12 max|a| + 1e-15 (compare_numbers.py;
#   the node sums near the cut add the two ranks' partial sums, one process
#   adds all terms in one sequence: round-off, docs/parallel.md; the absolute
#   1e-15 covers TotalMomentum, which is 0 to round-off for the symmetric disks).
#   mpi_cli_mpmice (KEEP_DECK=ON, PATCHES=[2,2,1]): MPMICE/massX.ups (decks
#   README A13) as it is but for its patches: the cuts x = y = 2.5 go through
#   the burning cube; its checkpoint at t = 2.5e-4 of 5e-4 s; compared: every
#   .dat file (TotalMass, KineticEnergy, totalMassBurned: saves added) and p.x, p.velocity, p.mass,
#   press_CC, rho_CC, temp_CC, g.temperature (VARS), with REL = 0: only the
#   absolute 1e-15 (session 21: the MPMICE particle scatters in patch order,
#   mpmice/BandScatter.h; measured 0 for 1 vs 2, 2 -> 1, 1 -> 2 and 2 -> 4;
#   session 18 measured 7.7e-12 with per-rank sums, docs/parallel.md
#   "MPMICE on ranks").
# Variables: TEPHRA, MPIEXEC, PYTHON, DECK_IN, WORK, COMPARE; optional
# REL (relative bound, default 1e-12), PATCHES (default [2,1,1]), VARS (default p.x p.velocity p.stress),
# KEEP_DECK (ON: only the patches are changed).
cmake_minimum_required(VERSION 3.16)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
endfunction()

function(expect_same_output a b what)
  set(pairs)
  foreach(var ${VARS})
    foreach(dir ${a} ${b})
      execute_process(COMMAND ${TEPHRA} extract ${dir} --var ${var} --step last
                      OUTPUT_FILE ${dir}.${var}.txt RESULT_VARIABLE rc)
      if(NOT rc EQUAL 0)
        message(FATAL_ERROR "${what}: extract ${var} of ${dir} failed (${rc})")
      endif()
    endforeach()
    list(APPEND pairs ${a}.${var}.txt ${b}.${var}.txt)
  endforeach()
  execute_process(COMMAND ${PYTHON} ${COMPARE} ${a} ${b} ${REL} 1e-15 ${pairs}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what}: ${out}${err}")
  endif()
  message(STATUS "${what}: ${out}")
endfunction()

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(READ ${DECK_IN} deck)
if(NOT DEFINED REL)
  set(REL 1e-12)
endif()
if(NOT DEFINED PATCHES)
  set(PATCHES [2,1,1])
endif()
if(NOT DEFINED VARS)
  set(VARS p.x p.velocity p.stress)
else()
  string(REPLACE "," ";" VARS "${VARS}")  # given comma-separated
endif()
string(REGEX REPLACE "<patches>[^<]*</patches>" "<patches>${PATCHES}</patches>" deck "${deck}")
if(KEEP_DECK)  # massX saves no .dat sums: TotalMass, KineticEnergy, totalMassBurned added
  string(REGEX REPLACE "(<checkpoint[^>]*/>)"
         "<save label=\"TotalMass\"/><save label=\"KineticEnergy\"/><save label=\"totalMassBurned\"/>\\1"
         deck "${deck}")
else()
  string(REGEX REPLACE "<extraCells>[^<]*</extraCells>" "<extraCells>[1,1,1]</extraCells>" deck "${deck}")
  string(REGEX REPLACE "<interpolator>[^<]*</interpolator>" "<interpolator>gimp</interpolator>" deck "${deck}")
  string(REGEX REPLACE "<checkpoint[^>]*/>" "<checkpoint cycle=\"2\" interval=\"0.7\"/>" deck "${deck}")
  string(REGEX REPLACE "<outputInterval>[^<]*</outputInterval>" "<outputInterval>0.1</outputInterval>" deck "${deck}")
endif()
file(WRITE ${WORK}/disks2.ups "${deck}")

set(MPI2 ${MPIEXEC} -n 2)
run(${TEPHRA} ${WORK}/disks2.ups --output ${WORK}/np1 --quiet)
run(${MPI2} ${TEPHRA} ${WORK}/disks2.ups --output ${WORK}/np2 --quiet)
expect_same_output(${WORK}/np1 ${WORK}/np2 "1 vs 2 ranks")

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
