{
  "id" : 1800000000200,
  "name" : "NoEntryPoint",
  "comment" : "",
  "relativeDirectory" : "broken",
  "variables" : [],
  "masterPlan" : false,
  "utilityThreshold" : 0.1,
  "preCondition" : null,
  "runtimeCondition" : null,
  "entryPoints" : [],
  "states" : [
    {
      "type" : "State",
      "id" : 1800000000202,
      "name" : "Idle",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1800000000200,
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "outTransitions" : [],
      "inTransitions" : []
    }
  ],
  "transitions" : [],
  "synchronisations" : []
}
