{
  "id" : 1402488634525,
  "name" : "Older",
  "comment" : "",
  "relativeDirectory" : "",
  "variables" : [],
  "masterPlan" : false,
  "utilityThreshold" : 0.1,
  "preCondition" : null,
  "runtimeCondition" : null,
  "entryPoints" : [
    {
      "id" : 1402488634526,
      "name" : "MISSING_NAME",
      "comment" : "",
      "successRequired" : false,
      "minCardinality" : 0,
      "maxCardinality" : 2147483647,
      "task" : "taskrepository.tsk#1225112227903",
      "state" : 1402488634527,
      "plan" : 1402488634525
    }
  ],
  "states" : [
    {
      "type" : "State",
      "id" : 1402488634527,
      "name" : "Default Name",
      "comment" : "",
      "entryPoint" : 1402488634526,
      "parentPlan" : 1402488634525,
      "abstractPlans" : "behaviours/Blink.beh#5764607523034234881, ",
      "parametrisations" : [],
      "outTransitions" : [
        1402488634535
      ],
      "inTransitions" : []
    },
    {
      "type" : "State",
      "id" : 1402488634528,
      "name" : "Default Name",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1402488634525,
      "abstractPlans" : [
        "behaviours/Blink.beh#5764607523034234881"
      ],
      "variableBindings" : [],
      "outTransitions" : [
        1402488634536
      ],
      "inTransitions" : [
        1402488634535
      ]
    },
    {
      "type" : "TerminalState",
      "id" : 1402488634529,
      "name" : "Failed",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1402488634525,
      "plans" : "",
      "parametrisations" : [],
      "outTransitions" : [],
      "inTransitions" : [
        1402488634536
      ],
      "success" : false,
      "postCondition" : null
    }
  ],
  "transitions" : [
    {
      "id" : 1402488634535,
      "name" : "FromDefault NameToDefault Name",
      "comment" : "MISSING_COMMENT",
      "inState" : 1402488634527,
      "outState" : 1402488634528,
      "preCondition" : {
        "id" : 1402488634545,
        "name" : "MISSING_NAME",
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
      "id" : 1402488634536,
      "name" : "MISSING_NAME",
      "comment" : "",
      "inState" : 1402488634528,
      "outState" : 1402488634529,
      "preCondition" : null,
      "synchronisation" : null
    }
  ],
  "synchronisations" : []
}
