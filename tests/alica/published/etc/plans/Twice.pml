{
  "comment": "Saved by hand: members named twice that change nothing gfec reads",
  "entryPoints": [
    {
      "id": 2100000000000000041,
      "name": "",
      "state": 2100000000000000042,
      "task": "taskrepository.tsk#2100000000000000101"
    }
  ],
  "id": 2100000000000000040,
  "name": "Twice",
  "states": [
    {
      "confAbstractPlanWrappers": [],
      "id": 2100000000000000042,
      "name": "Idle",
      "positionWeb": {
        "x": 428,
        "y": 200
      },
      "positionWeb": {
        "x": 430,
        "y": 200
      },
      "type": "State",
      "name": "Idle"
    }
  ],
  "transitions": [],
  "comment": "a second comment"
}
