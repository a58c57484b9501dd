{
  "id" : 1542881176278,
  "name" : "Master",
  "comment" : "",
  "relativeDirectory" : "",
  "variables" : [],
  "masterPlan" : true,
  "utilityThreshold" : 0.1,
  "preCondition" : null,
  "runtimeCondition" : null,
  "entryPoints" : [
    {
      "id" : 1542881176279,
      "name" : "MISSING_NAME",
      "comment" : "",
      "successRequired" : false,
      "minCardinality" : 0,
      "maxCardinality" : 2147483647,
      "task" : "TaskRepository.tsk#9007199254740995",
      "state" : 1542881176280,
      "plan" : 1542881176278
    }
  ],
  "states" : [
    {
      "type" : "State",
      "id" : 1542881176280,
      "name" : "Search",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1542881176278,
      "confAbstractPlanWrappers" : [
        {
          "id" : 1542881177280,
          "name" : "1542881177280",
          "comment" : "",
          "abstractPlan" : "Behaviours/SearchItem.beh#1700000000000",
          "configuration" : null
        }
      ],
      "variableBindings" : [],
      "outTransitions" : [
        1542881176298
      ],
      "inTransitions" : []
    },
    {
      "type" : "State",
      "id" : 1542881176281,
      "name" : "Fetch Item",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1542881176278,
      "confAbstractPlanWrappers" : [
        {
          "id" : 1542881177281,
          "name" : "1542881177281",
          "comment" : "",
          "abstractPlan" : "Fetch.pml#4611686018427387905",
          "configuration" : null
        }
      ],
      "variableBindings" : [],
      "outTransitions" : [
        1542881176299,
        1542881176300
      ],
      "inTransitions" : [
        1542881176298,
        1542881176301
      ]
    },
    {
      "type" : "State",
      "id" : 1542881176282,
      "name" : "Retry",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1542881176278,
      "confAbstractPlanWrappers" : [
        {
          "id" : 1542881177282,
          "name" : "1542881177282",
          "comment" : "",
          "abstractPlan" : "Behaviours/Park.beh#1700000000003",
          "configuration" : null
        }
      ],
      "variableBindings" : [],
      "outTransitions" : [
        1542881176301
      ],
      "inTransitions" : [
        1542881176300
      ]
    },
    {
      "type" : "TerminalState",
      "id" : 1542881176283,
      "name" : "Done",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1542881176278,
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "outTransitions" : [],
      "inTransitions" : [
        1542881176299
      ],
      "success" : true,
      "postCondition" : null
    }
  ],
  "transitions" : [
    {
      "id" : 1542881176298,
      "name" : "Found",
      "comment" : "",
      "inState" : 1542881176280,
      "outState" : 1542881176281,
      "preCondition" : {
        "id" : 1542881176308,
        "name" : "ItemSeen",
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
      "id" : 1542881176299,
      "name" : "Fetched",
      "comment" : "",
      "inState" : 1542881176281,
      "outState" : 1542881176283,
      "preCondition" : {
        "id" : 1542881176309,
        "name" : "AnyChildSuccess",
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
      "id" : 1542881176300,
      "name" : "FetchLost",
      "comment" : "",
      "inState" : 1542881176281,
      "outState" : 1542881176282,
      "preCondition" : {
        "id" : 1542881176310,
        "name" : "AnyChildFailure",
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
      "id" : 1542881176301,
      "name" : "TryAgain",
      "comment" : "",
      "inState" : 1542881176282,
      "outState" : 1542881176281,
      "preCondition" : {
        "id" : 1542881176311,
        "name" : "Parked",
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
