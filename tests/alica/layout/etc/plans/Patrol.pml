{
  "id" : 1900000000000,
  "name" : "Patrol",
  "comment" : "",
  "masterPlan" : true,
  "libraryName" : "tests",
  "blackboard" : [],
  "preCondition" : null,
  "runtimeCondition" : null,
  "entryPoints" : [
    {
      "id" : 1900000000001,
      "name" : "1900000000001",
      "comment" : "",
      "successRequired" : false,
      "minCardinality" : 0,
      "maxCardinality" : 2147483647,
      "task" : "taskrepository.tsk#1900000009001",
      "state" : 1900000000010,
      "plan" : 1900000000000
    }
  ],
  "states" : [
    {
      "type" : "State",
      "id" : 1900000000010,
      "name" : "init",
      "comment" : "",
      "confAbstractPlanWrappers" : [
        {
          "id" : 19000000000100,
          "name" : "19000000000100",
          "comment" : "",
          "abstractPlan" : "Look.beh#1900000001000",
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
      "type" : "State",
      "id" : 1900000000011,
      "name" : "Wait",
      "comment" : "",
      "confAbstractPlanWrappers" : [
        {
          "id" : 19000000000110,
          "name" : "19000000000110",
          "comment" : "",
          "abstractPlan" : "Anything.plc#1900000003000",
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
      "type" : "State",
      "id" : 1900000000012,
      "name" : "Sweep",
      "comment" : "",
      "confAbstractPlanWrappers" : [
        {
          "id" : 19000000000120,
          "name" : "19000000000120",
          "comment" : "",
          "abstractPlan" : "sub/Sweeps.pty#1900000004000",
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
      "id" : 1900000000013,
      "name" : "Done",
      "comment" : "",
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "success" : true,
      "postCondition" : null
    }
  ],
  "transitions" : [
    {
      "id" : 1900000000020,
      "name" : "1900000000020",
      "comment" : "",
      "inState" : 1900000000010,
      "outState" : 1900000000011,
      "condition" : "ConditionRepository.cnd#1900000002001",
      "keyMapping" : {
        "input" : [],
        "output" : []
      },
      "preCondition" : {
        "id" : 1900000000520,
        "name" : "",
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
      "id" : 1900000000021,
      "name" : "1900000000021",
      "comment" : "",
      "inState" : 1900000000011,
      "outState" : 1900000000012,
      "condition" : "ConditionRepository.cnd#1900000002002",
      "keyMapping" : {
        "input" : [],
        "output" : []
      },
      "preCondition" : {
        "id" : 1900000000521,
        "name" : "",
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
      "id" : 1900000000022,
      "name" : "1900000000022",
      "comment" : "",
      "inState" : 1900000000012,
      "outState" : 1900000000013,
      "condition" : "ConditionRepository.cnd#1",
      "keyMapping" : {
        "input" : [],
        "output" : []
      },
      "preCondition" : {
        "id" : 1900000000522,
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
