{
  "id" : 1800000000000,
  "name" : "Ignored",
  "comment" : "",
  "relativeDirectory" : "broken",
  "variables" : [],
  "masterPlan" : false,
  "utilityThreshold" : 0.1,
  "preCondition" : null,
  "runtimeCondition" : {
    "id" : 1800000000050,
    "name" : "StillUseful",
    "comment" : "",
    "enabled" : true,
    "conditionString" : "",
    "pluginName" : "DefaultPlugin",
    "variables" : [],
    "quantifiers" : []
  },
  "entryPoints" : [
    {
      "id" : 1800000000001,
      "name" : "MISSING_NAME",
      "comment" : "",
      "successRequired" : false,
      "minCardinality" : 2,
      "maxCardinality" : 4,
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
      "type" : "TerminalState",
      "id" : 1800000000003,
      "name" : "End",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1800000000000,
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "outTransitions" : [],
      "inTransitions" : [
        1800000000020
      ],
      "success" : true,
      "postCondition" : null
    }
  ],
  "transitions" : [
    {
      "id" : 1800000000020,
      "name" : "Sync",
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
      "synchronisation" : 1800000000040
    }
  ],
  "synchronisations" : [
    {
      "id" : 1800000000040,
      "name" : "Together",
      "comment" : "",
      "talkTimeout" : 30,
      "syncTimeout" : 10000,
      "failOnSyncTimeout" : false,
      "plan" : 1800000000000,
      "syncedTransitions" : [
        1800000000020
      ]
    }
  ]
}
