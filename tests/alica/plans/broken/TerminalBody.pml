{
  "id" : 1800000000100,
  "name" : "TerminalBody",
  "comment" : "",
  "relativeDirectory" : "broken",
  "variables" : [],
  "masterPlan" : false,
  "utilityThreshold" : 0.1,
  "preCondition" : null,
  "runtimeCondition" : null,
  "entryPoints" : [
    {
      "id" : 1800000000101,
      "name" : "MISSING_NAME",
      "comment" : "",
      "successRequired" : false,
      "minCardinality" : 0,
      "maxCardinality" : 2147483647,
      "task" : "TaskRepository.tsk#9007199254740995",
      "state" : 1800000000102,
      "plan" : 1800000000100
    }
  ],
  "states" : [
    {
      "type" : "State",
      "id" : 1800000000102,
      "name" : "Drive",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1800000000100,
      "confAbstractPlanWrappers" : [
        {
          "id" : 1800000000110,
          "name" : "",
          "comment" : "",
          "abstractPlan" : "../Behaviours/DriveToItem.beh#1700000000001",
          "configuration" : null
        }
      ],
      "variableBindings" : [],
      "outTransitions" : [
        1800000000120
      ],
      "inTransitions" : []
    },
    {
      "type" : "TerminalState",
      "id" : 1800000000103,
      "name" : "Parked",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1800000000100,
      "success" : true,
      "postCondition" : null,
      "confAbstractPlanWrappers" : [
        {
          "id" : 1800000000111,
          "name" : "",
          "comment" : "",
          "abstractPlan" : "../Behaviours/Park.beh#1700000000003",
          "configuration" : null
        }
      ],
      "variableBindings" : [],
      "outTransitions" : [],
      "inTransitions" : [
        1800000000120
      ]
    }
  ],
  "transitions" : [
    {
      "id" : 1800000000120,
      "name" : "Arrive",
      "comment" : "",
      "inState" : 1800000000102,
      "outState" : 1800000000103,
      "preCondition" : {
        "id" : 1800000000130,
        "name" : "ArriveCond",
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
