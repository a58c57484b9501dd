{
  "id" : 1800000000000,
  "name" : "LeavesTerminal",
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
      "name" : "Work",
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
      "name" : "Finished",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1800000000000,
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "outTransitions" : [
        1800000000021
      ],
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
      "name" : "Finish",
      "comment" : "",
      "inState" : 1800000000002,
      "outState" : 1800000000003,
      "preCondition" : {
        "id" : 1800000000030,
        "name" : "AllDone",
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
      "name" : "Restart",
      "comment" : "",
      "inState" : 1800000000003,
      "outState" : 1800000000002,
      "preCondition" : {
        "id" : 1800000000031,
        "name" : "Again",
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
