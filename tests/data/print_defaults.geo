// Prints Reparam's option defaults (CTest options.defaults)
Printf("CompoundParametrization=%g CompoundRepair=%g CompoundFillHoles=%g CompoundReport=%g CompoundSplit=%g",
       Mesh.CompoundParametrization, Mesh.CompoundRepair,
       Mesh.CompoundFillHoles, Mesh.CompoundReport, Mesh.CompoundSplit);
Printf(StrCat("CompoundReportFile='", Mesh.CompoundReportFile, "'"));
