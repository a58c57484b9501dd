{
  "id" : 4611686018427387905,
  "name" : "Fetch",
  "comment" : "",
  "relativeDirectory" : "",
  "variables" : [],
  "masterPlan" : false,
  "utilityThreshold" : 0.1,
  "preCondition" : null,
  "runtimeCondition" : null,
  "entryPoints" : [
    {
      "id" : 4611686018427387906,
      "name" : "MISSING_NAME",
      "comment" : "",
      "successRequired" : false,
      "minCardinality" : 0,
      "maxCardinality" : 2147483647,
      "task" : "TaskRepository.tsk#9007199254740995",
      "state" : 4611686018427387907,
      "plan" : 4611686018427387905
    }
  ],
  "states" : [
    {
      "type" : "State",
      "id" : 4611686018427387907,
      "name" : "Go",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 4611686018427387905,
      "confAbstractPlanWrappers" : [
        {
          "id" : 4611686018427388907,
          "name" : "4611686018427388907",
          "comment" : "",
          "abstractPlan" : "Behaviours/DriveToItem.beh#1700000000001",
          "configuration" : null
        }
      ],
      "variableBindings" : [],
      "outTransitions" : [
        4611686018427387925,
        4611686018427387927
      ],
      "inTransitions" : []
    },
    {
      "type" : "State",
      "id" : 4611686018427387909,
      "name" : "Grab",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 4611686018427387905,
      "confAbstractPlanWrappers" : [
        {
          "id" : 4611686018427388909,
          "name" : "4611686018427388909",
          "comment" : "",
          "abstractPlan" : "Behaviours/PickUp.beh#1700000000002",
          "configuration" : null
        }
      ],
      "variableBindings" : [],
      "outTransitions" : [
        4611686018427387926
      ],
      "inTransitions" : [
        4611686018427387925
      ]
    },
    {
      "type" : "TerminalState",
      "id" : 4611686018427387911,
      "name" : "Got",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 4611686018427387905,
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "outTransitions" : [],
      "inTransitions" : [
        4611686018427387926
      ],
      "success" : true,
      "postCondition" : null
    },
    {
      "type" : "TerminalState",
      "id" : 4611686018427387913,
      "name" : "Lost",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 4611686018427387905,
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "outTransitions" : [],
      "inTransitions" : [
        4611686018427387927
      ],
      "success" : false,
      "postCondition" : null
    }
  ],
  "transitions" : [
    {
      "id" : 4611686018427387925,
      "name" : "Go2Grab",
      "comment" : "",
      "inState" : 4611686018427387907,
      "outState" : 4611686018427387909,
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
      "id" : 4611686018427387926,
      "name" : "Grab2Got",
      "comment" : "",
      "inState" : 4611686018427387909,
      "outState" : 4611686018427387911,
      "preCondition" : {
        "id" : 4611686018427387936,
        "name" : "Holding",
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
      "id" : 4611686018427387927,
      "name" : "Go2Lost",
      "comment" : "",
      "inState" : 4611686018427387907,
      "outState" : 4611686018427387913,
      "preCondition" : {
        "id" : 4611686018427387937,
        "name" : "Stuck",
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
