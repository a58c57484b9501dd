{
  "id" : 1800000000000,
  "name" : "SelfLoop",
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
      "name" : "Spin",
      "comment" : "",
      "entryPoint" : null,
      "parentPlan" : 1800000000000,
      "confAbstractPlanWrappers" : [],
      "variableBindings" : [],
      "outTransitions" : [
        1800000000020
      ],
      "inTransitions" : [
        1800000000020
      ]
    }
  ],
  "transitions" : [
    {
      "id" : 1800000000020,
      "name" : "Again",
      "comment" : "",
      "inState" : 1800000000002,
      "outState" : 1800000000002,
      "preCondition" : {
        "id" : 1800000000030,
        "name" : "Dizzy",
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
