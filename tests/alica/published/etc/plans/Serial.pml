{
  "comment": "Runs a part that was never saved: the nearest file name is this plan's own",
  "entryPoints": [
    {
      "id": 2100000000000000061,
      "name": "",
      "state": 2100000000000000062,
      "task": "taskrepository.tsk#2100000000000000101"
    }
  ],
  "id": 2100000000000000060,
  "name": "Serial",
  "states": [
    {
      "confAbstractPlanWrappers": [
        {
          "abstractPlan": "SerialPart.pml#2100000000000000070",
          "configuration": null,
          "id": 2100000000000000063,
          "name": ""
        }
      ],
      "id": 2100000000000000062,
      "name": "RunPart",
      "type": "State"
    }
  ],
  "transitions": []
}
