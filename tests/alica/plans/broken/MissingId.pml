{
  "id" : 1800000000000,
  "name" : "MissingId",
  "comment" : "",
  "relativeDirectory" : "broken",
  "variables" : [],
  "masterPlan" : false,
  "utilityThreshold" : 0.1,
  "preCondition" : null,
  "runtimeCondition" : null,
  "entryPoints" : [
    {
      "id" : 1800000000001,
      "name" : "MISSING_NAME",
      "comment" : "",
      "successRequired" : false,
      "minCardinality" : 0,
      "maxCardinality" : 2147483647,
      "task" : "TaskRepository.tsk#9007199254740995",
      "state" : 1800000000002,
      "plan" : 1800000000000
    }
  ],
  "states" : [
    {
      "type" : "State",
      "id" : 1800000000002,
      "name" : "Start",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1800000000000,
      "confAbstractPlanWrappers" : [
        {
          "id" : 1800000001002,
          "name" : "1800000001002",
          "comment" : "",
          "abstractPlan" : "Behaviours/Park.beh#1700000000099",
          "configuration" : null
        }
      ],
      "variableBindings" : [],
      "outTransitions" : [],
      "inTransitions" : []
    }
  ],
  "transitions" : [],
  "synchronisations" : []
}
