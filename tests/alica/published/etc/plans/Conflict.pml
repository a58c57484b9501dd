{
  "comment": "Saved by hand: the entry point names its state twice, and the second one differs",
  "entryPoints": [
    {
      "id": 2100000000000000051,
      "name": "",
      "state": 2100000000000000052,
      "task": "taskrepository.tsk#2100000000000000101",
      "state": 2100000000000000053
    }
  ],
  "id": 2100000000000000050,
  "name": "Conflict",
  "states": [
    {
      "confAbstractPlanWrappers": [],
      "id": 2100000000000000052,
      "name": "Start",
      "type": "State"
    },
    {
      "confAbstractPlanWrappers": [],
      "id": 2100000000000000053,
      "name": "Other",
      "type": "State"
    }
  ],
  "transitions": [
    {
      "id": 2100000000000000054,
      "inState": 2100000000000000052,
      "name": "",
      "outState": 2100000000000000053,
      "preCondition": null
    }
  ]
}
