{
  "blackboard": [
    {
      "access": "input",
      "comment": "",
      "id": 776883745699711074,
      "key": "flag",
      "type": "bool"
    }
  ],
  "comment": "",
  "entryPoints": [
    {
      "comment": "",
      "id": 3807068659782313210,
      "isDynamic": false,
      "maxCardinality": 2147483647,
      "minCardinality": 0,
      "name": "",
      "plan": 3807068659782313208,
      "positionWeb": {
        "x": 200,
        "y": 212
      },
      "state": 3807068659782313209,
      "successRequired": false,
      "task": "taskrepository.tsk#1225112227903"
    }
  ],
  "frequency": 0,
  "id": 3807068659782313208,
  "implementationName": "",
  "inheritBlackboard": false,
  "libraryName": "tests",
  "masterPlan": true,
  "name": "Newest",
  "preCondition": null,
  "runtimeCondition": null,
  "states": [
    {
      "comment": "",
      "confAbstractPlanWrappers": [
        {
          "abstractPlan": "behaviours/Blink.beh#5764607523034234881",
          "comment": "",
          "configuration": null,
          "id": 3807068659782313216,
          "keyMapping": {
            "input": [],
            "output": []
          },
          "name": ""
        }
      ],
      "entryPoint": 3807068659782313210,
      "id": 3807068659782313209,
      "inTransitions": [],
      "name": "Blinking",
      "outTransitions": [],
      "parentPlan": 3807068659782313208,
      "positionWeb": {
        "x": 200,
        "y": 212
      },
      "type": "State",
      "variableBindings": []
    },
    {
      "comment": "",
      "confAbstractPlanWrappers": [
        {
          "abstractPlan": "Older.pml#1402488634525",
          "comment": "",
          "configuration": null,
          "id": 3807068659782313218,
          "keyMapping": {
            "input": [],
            "output": []
          },
          "name": ""
        }
      ],
      "entryPoint": null,
      "id": 3807068659782313211,
      "inTransitions": [],
      "name": "Older",
      "outTransitions": [],
      "parentPlan": 3807068659782313208,
      "positionWeb": {
        "x": 200,
        "y": 212
      },
      "type": "State",
      "variableBindings": []
    },
    {
      "comment": "",
      "confAbstractPlanWrappers": [],
      "entryPoint": null,
      "id": 3807068659782313212,
      "inTransitions": [],
      "name": "Done",
      "outTransitions": [],
      "parentPlan": 3807068659782313208,
      "positionWeb": {
        "x": 200,
        "y": 212
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
      "condition": "ConditionRepository.cnd#9223372036854775807",
      "id": 3807068659782313219,
      "inState": 3807068659782313209,
      "keyMapping": {
        "input": [
          {
            "childKey": "flag",
            "parentKey": "flag",
            "value": null
          }
        ],
        "output": []
      },
      "name": "",
      "outState": 3807068659782313211,
      "pointsWeb": [],
      "preCondition": {
        "comment": "",
        "conditionString": "",
        "enabled": true,
        "id": 3807068659782313220,
        "name": "",
        "pluginName": "DefaultPlugin",
        "quantifiers": [],
        "variables": []
      },
      "synchronisation": null
    },
    {
      "comment": "",
      "condition": "ConditionRepository.cnd#1",
      "id": 3807068659782313221,
      "inState": 3807068659782313211,
      "keyMapping": {
        "input": [],
        "output": []
      },
      "name": "",
      "outState": 3807068659782313212,
      "pointsWeb": [],
      "preCondition": null,
      "synchronisation": null
    }
  ],
  "utilityThreshold": 0.0,
  "variables": []
}
