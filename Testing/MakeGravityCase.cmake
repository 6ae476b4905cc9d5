# ctest fixture: a copy of the OpenFOAM cavity with a constant/g (gravity
# along -z) and a scene on it using "view_up": "auto".
#   cmake -DDATA=<data folder> -DOUT=<folder> -P MakeGravityCase.cmake
file(REMOVE_RECURSE "${OUT}")
file(COPY "${DATA}/openfoam_cavity/cavity" DESTINATION "${OUT}")
file(WRITE "${OUT}/cavity/constant/g" "FoamFile\n{\n    class uniformDimensionedVectorField;\n    object g;\n}\n\ndimensions [0 1 -2 0 0 0 0];\nvalue (0 0 -9.81);\n")
file(WRITE "${OUT}/gravity.json" "{ \"datasets\": { \"cavity\": { \"path\": \"cavity/case.foam\" } },\n  \"representations\": [ { \"type\": \"outline\", \"dataset\": \"cavity\" } ],\n  \"camera\": { \"view_up\": \"auto\" } }\n")
file(WRITE "${OUT}/no_gravity.json" "{ \"datasets\": { \"v\": { \"source\": \"vortex\" } },\n  \"representations\": [ { \"type\": \"outline\", \"dataset\": \"v\" } ],\n  \"camera\": { \"view_up\": \"auto\" } }\n")
