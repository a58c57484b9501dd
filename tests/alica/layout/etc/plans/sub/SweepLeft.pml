{
  "id" : 1900000005000,
  "name" : "SweepLeft",
  "comment" : "",
  "relativeDirectory" : "old",
  "masterPlan" : false,
  "preCondition" : null,
  "runtimeCondition" : null,
  "entryPoints" : [
    {
      "id" : 1900000005001,
      "name" : "MISSING_NAME",
      "comment" : "",
      "successRequired" : false,
      "minCardinality" : 0,
      "maxCardinality" : 2147483647,
      "task" : "taskrepository.tsk#1900000009001",
      "state" : 1900000005010,
      "plan" : 1900000005000
    }
  ],
  "states" : [
    {
      "type" : "State",
      "id" : 1900000005010,
      "name" : "Turning",
      "comment" : "",
      "confAbstractPlanWrappers" : [
        {
          "id" : 19000000050100,
          "name" : "19000000050100",
          "comment" : "",
          "abstractPlan" : "Behaviour/Turn.beh#1900000001001",
          "configuration" : null,
          "keyMapping" : {
            "input" : [],
            "output" : []
          }
        }
      ],
      "variableBindings" : []
    },
    {
      "type" : "TerminalState",
      "id" : 1900000005011,
      "name" : "Swept",
      "comment" : "",
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "success" : true,
      "postCondition" : null
    }
  ],
  "transitions" : [
    {
      "id" : 1900000005020,
      "name" : "Turned",
      "comment" : "",
      "inState" : 1900000005010,
      "outState" : 1900000005011,
      "condition" : "ConditionRepository.cnd#1900000002003",
      "keyMapping" : {
        "input" : [],
        "output" : []
      },
      "preCondition" : {
        "id" : 1900000005520,
        "name" : "",
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
  "synchronisations" : [],
  "variables" : []
}
