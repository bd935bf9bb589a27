# Installs the build into a staging folder (DESTDIR) and imports the installed package from there,
# with the interpreter the module was built for: what `cmake --install` gives a user works.
# Variables: BUILD_DIR, STAGE (a folder of this test's own), PREFIX (CMAKE_INSTALL_PREFIX),
# SITE (the package's install folder, absolute or under PREFIX), PYTHON.
file(REMOVE_RECURSE ${STAGE})
execute_process(COMMAND ${CMAKE_COMMAND} -E env DESTDIR=${STAGE} ${CMAKE_COMMAND} --install ${BUILD_DIR}
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${rc}")
endif()
if(IS_ABSOLUTE ${SITE})
  set(site ${STAGE}${SITE})
else()
  set(site ${STAGE}${PREFIX}/${SITE})
endif()
foreach(f __init__.py __init__.pyi py.typed)
  if(NOT EXISTS ${site}/cgal_ext_geodesics/${f})
    message(FATAL_ERROR "not installed: ${site}/cgal_ext_geodesics/${f}")
  endif()
endforeach()
set(check [=[
import os, sys
import numpy as np
import cgal_ext_geodesics as geo
here = os.path.realpath(os.path.dirname(geo.__file__))
assert here == os.path.realpath(sys.argv[1]), f"imported from {here}, not from the installed {sys.argv[1]}"
V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], dtype=float)
d = geo.distances(V, [[0, 1, 2], [1, 3, 2]], 0)
assert abs(d[3] - 2 ** 0.5) < 1e-15, d
print("installed package imported from", here)
]=])
# (from the stage: python -c puts the working folder first in sys.path)
execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${site} ${PYTHON} -c "${check}" ${site}/cgal_ext_geodesics
                WORKING_DIRECTORY ${STAGE}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed package does not import: ${rc}")
endif()
