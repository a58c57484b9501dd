{
  "id" : 1800000000000,
  "name" : "SecondPair",
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
      "name" : "A",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1800000000000,
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "outTransitions" : [
        1800000000020,
        1800000000021
      ],
      "inTransitions" : []
    },
    {
      "type" : "State",
      "id" : 1800000000003,
      "name" : "B",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1800000000000,
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "outTransitions" : [],
      "inTransitions" : [
        1800000000020,
        1800000000021
      ]
    }
  ],
  "transitions" : [
    {
      "id" : 1800000000020,
      "name" : "First",
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
    },
    {
      "id" : 1800000000021,
      "name" : "Second",
      "comment" : "",
      "inState" : 1800000000002,
      "outState" : 1800000000003,
      "preCondition" : {
        "id" : 1800000000031,
        "name" : "Set",
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
