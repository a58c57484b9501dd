{
  "id" : 1800000000300,
  "name" : "SharedEntry",
  "comment" : "",
  "relativeDirectory" : "broken",
  "variables" : [],
  "masterPlan" : false,
  "utilityThreshold" : 0.1,
  "preCondition" : null,
  "runtimeCondition" : null,
  "entryPoints" : [
    {
      "id" : 1800000000301,
      "name" : "Left",
      "comment" : "",
      "successRequired" : false,
      "minCardinality" : 0,
      "maxCardinality" : 2147483647,
      "task" : "TaskRepository.tsk#9007199254740995",
      "state" : 1800000000302,
      "plan" : 1800000000300
    },
    {
      "id" : 1800000000304,
      "name" : "Right",
      "comment" : "",
      "successRequired" : false,
      "minCardinality" : 0,
      "maxCardinality" : 2147483647,
      "task" : "TaskRepository.tsk#9007199254740995",
      "state" : 1800000000302,
      "plan" : 1800000000300
    }
  ],
  "states" : [
    {
      "type" : "State",
      "id" : 1800000000302,
      "name" : "Both",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1800000000300,
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "outTransitions" : [],
      "inTransitions" : []
    }
  ],
  "transitions" : [],
  "synchronisations" : []
}
