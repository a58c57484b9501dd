{
  "blackboard": [],
  "comment": "Each transition names its condition in the repository; the designer still writes a preCondition object beside it, which decides nothing",
  "entryPoints": [
    {
      "comment": "",
      "id": 2100000000000000011,
      "isDynamic": false,
      "maxCardinality": 2147483647,
      "minCardinality": 0,
      "name": "",
      "plan": 2100000000000000010,
      "positionWeb": {
        "x": 200,
        "y": 212
      },
      "state": 2100000000000000012,
      "successRequired": false,
      "task": "taskrepository.tsk#2100000000000000101"
    }
  ],
  "frequency": 0,
  "id": 2100000000000000010,
  "inheritBlackboard": false,
  "libraryName": "tests",
  "masterPlan": true,
  "name": "Leftover",
  "preCondition": null,
  "runtimeCondition": null,
  "states": [
    {
      "comment": "",
      "confAbstractPlanWrappers": [
        {
          "abstractPlan": "Wait.beh#2100000000000000001",
          "comment": "",
          "configuration": null,
          "id": 2100000000000000015,
          "keyMapping": {
            "input": [],
            "output": []
          },
          "name": ""
        }
      ],
      "entryPoint": 2100000000000000011,
      "id": 2100000000000000012,
      "inTransitions": [],
      "name": "Waiting",
      "outTransitions": [
        2100000000000000020
      ],
      "parentPlan": 2100000000000000010,
      "positionWeb": {
        "x": 428,
        "y": 200
      },
      "type": "State",
      "variableBindings": []
    },
    {
      "comment": "",
      "confAbstractPlanWrappers": [],
      "entryPoint": null,
      "id": 2100000000000000013,
      "inTransitions": [
        2100000000000000020
      ],
      "name": "Checking",
      "outTransitions": [
        2100000000000000021
      ],
      "parentPlan": 2100000000000000010,
      "positionWeb": {
        "x": 686,
        "y": 200
      },
      "type": "State",
      "variableBindings": []
    },
    {
      "comment": "",
      "confAbstractPlanWrappers": [],
      "entryPoint": null,
      "id": 2100000000000000014,
      "inTransitions": [
        2100000000000000021
      ],
      "name": "Done",
      "outTransitions": [],
      "parentPlan": 2100000000000000010,
      "positionWeb": {
        "x": 944,
        "y": 200
      },
      "postCondition": null,
      "success": true,
      "type": "TerminalState",
      "variableBindings": []
    }
  ],
  "synchronisations": [],
  "transitions": [
    {
      "comment": "",
      "condition": "ConditionRepository.cnd#11",
      "id": 2100000000000000020,
      "inState": 2100000000000000012,
      "keyMapping": {
        "input": [],
        "output": []
      },
      "name": "Ready",
      "outState": 2100000000000000013,
      "pointsWeb": [],
      "preCondition": {
        "comment": "",
        "conditionString": "",
        "enabled": true,
        "id": 2100000000000000030,
        "name": "MISSING_NAME",
        "pluginName": "DefaultPlugin",
        "quantifiers": [
          {
            "comment": "",
            "id": 2100000000000000031,
            "name": "MISSING_NAME",
            "quantifierType": "all",
            "scope": 2100000000000000010,
            "sorts": [
              "X"
            ]
          }
        ],
        "variables": []
      },
      "synchronisation": null
    },
    {
      "comment": "",
      "condition": "ConditionRepository.cnd#12",
      "id": 2100000000000000021,
      "inState": 2100000000000000013,
      "keyMapping": {
        "input": [],
        "output": []
      },
      "name": "",
      "outState": 2100000000000000014,
      "pointsWeb": [],
      "preCondition": {
        "comment": "",
        "conditionString": "",
        "enabled": true,
        "id": 2100000000000000032,
        "name": "",
        "pluginName": "DefaultPlugin",
        "quantifiers": [],
        "variables": []
      },
      "synchronisation": null
    }
  ],
  "utilityThreshold": 0.0,
  "variables": []
}
