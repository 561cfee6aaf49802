// Prints Reparam's option defaults (CTest options.defaults)
Printf("CompoundParametrization=%g CompoundRepair=%g CompoundFillHoles=%g CompoundReport=%g CompoundSplit=%g CompoundLayout=%g CompoundNoiseSize=%g CompoundCurveCorners=%g CompoundOptimize=%g",
       Mesh.CompoundParametrization, Mesh.CompoundRepair,
       Mesh.CompoundFillHoles, Mesh.CompoundReport, Mesh.CompoundSplit,
       Mesh.CompoundLayout, Mesh.CompoundNoiseSize, Mesh.CompoundCurveCorners,
       Mesh.CompoundOptimize);
Printf(StrCat("CompoundReportFile='", Mesh.CompoundReportFile, "'"));
