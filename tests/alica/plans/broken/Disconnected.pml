{
  "id" : 1800000000000,
  "name" : "Disconnected",
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
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "outTransitions" : [
        1800000000020
      ],
      "inTransitions" : []
    },
    {
      "type" : "State",
      "id" : 1800000000003,
      "name" : "Next",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1800000000000,
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "outTransitions" : [],
      "inTransitions" : [
        1800000000020
      ]
    },
    {
      "type" : "State",
      "id" : 1800000000004,
      "name" : "Island",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1800000000000,
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "outTransitions" : [],
      "inTransitions" : []
    }
  ],
  "transitions" : [
    {
      "id" : 1800000000020,
      "name" : "Go",
      "comment" : "",
      "inState" : 1800000000002,
      "outState" : 1800000000003,
      "preCondition" : {
        "id" : 1800000000030,
        "name" : "Ready",
        "comment" : "",
        "enabled" : true,
        "conditionString" : "",
        "pluginName" : "DefaultPlugin",
        "variables" : [],
        "quantifiers" : []
      },
      "synchronisation" : null
    }
  ],
  "synchronisations" : []
}
