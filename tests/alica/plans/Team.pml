{
  "id" : 1600000000000,
  "name" : "Team",
  "comment" : "",
  "relativeDirectory" : "",
  "variables" : [],
  "masterPlan" : false,
  "utilityThreshold" : 0.1,
  "preCondition" : null,
  "runtimeCondition" : null,
  "entryPoints" : [
    {
      "id" : 1600000000001,
      "name" : "MISSING_NAME",
      "comment" : "",
      "successRequired" : false,
      "minCardinality" : 0,
      "maxCardinality" : 2147483647,
      "task" : "TaskRepository.tsk#9007199254740997",
      "state" : 1600000000002,
      "plan" : 1600000000000
    },
    {
      "id" : 1600000000006,
      "name" : "Helper",
      "comment" : "",
      "successRequired" : false,
      "minCardinality" : 0,
      "maxCardinality" : 2147483647,
      "task" : "TaskRepository.tsk#9007199254740999",
      "state" : 1600000000004,
      "plan" : 1600000000000
    }
  ],
  "states" : [
    {
      "type" : "State",
      "id" : 1600000000002,
      "name" : "Lead",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1600000000000,
      "confAbstractPlanWrappers" : [
        {
          "id" : 1600000001002,
          "name" : "1600000001002",
          "comment" : "",
          "abstractPlan" : "Behaviours/DriveToItem.beh#1700000000001",
          "configuration" : null
        }
      ],
      "variableBindings" : [],
      "outTransitions" : [
        1600000000020
      ],
      "inTransitions" : []
    },
    {
      "type" : "State",
      "id" : 1600000000003,
      "name" : "Arrive",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1600000000000,
      "confAbstractPlanWrappers" : [
        {
          "id" : 1600000001003,
          "name" : "1600000001003",
          "comment" : "",
          "abstractPlan" : "Behaviours/Park.beh#1700000000003",
          "configuration" : null
        }
      ],
      "variableBindings" : [],
      "outTransitions" : [],
      "inTransitions" : [
        1600000000020
      ]
    },
    {
      "type" : "State",
      "id" : 1600000000004,
      "name" : "Guard",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1600000000000,
      "confAbstractPlanWrappers" : [
        {
          "id" : 1600000001004,
          "name" : "1600000001004",
          "comment" : "",
          "abstractPlan" : "Behaviours/Watch.beh#1700000000004",
          "configuration" : null
        }
      ],
      "variableBindings" : [],
      "outTransitions" : [
        1600000000021
      ],
      "inTransitions" : []
    },
    {
      "type" : "TerminalState",
      "id" : 1600000000005,
      "name" : "Relieved",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1600000000000,
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "outTransitions" : [],
      "inTransitions" : [
        1600000000021
      ],
      "success" : true,
      "postCondition" : null
    }
  ],
  "transitions" : [
    {
      "id" : 1600000000020,
      "name" : "",
      "comment" : "",
      "inState" : 1600000000002,
      "outState" : 1600000000003,
      "preCondition" : {
        "id" : 4611686018427387935,
        "name" : "Arrived",
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
      "id" : 1600000000021,
      "name" : "",
      "comment" : "",
      "inState" : 1600000000004,
      "outState" : 1600000000005,
      "preCondition" : {
        "id" : 1600000000031,
        "name" : "MISSING_NAME",
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
