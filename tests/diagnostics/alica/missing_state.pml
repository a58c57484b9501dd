{
  "id" : 100,
  "name" : "Fetch",
  "comment" : "a transition to a state the plan does not have, and a member given twice",
  "relativeDirectory" : "",
  "entryPoints" : [
    {
      "id" : 101,
      "name" : "Start",
      "state" : 102,
      "plan" : 100
    }
  ],
  "states" : [
    {
      "type" : "State",
      "id" : 102,
      "name" : "Go",
      "name" : "Go",
      "confAbstractPlanWrappers" : [],
      "outTransitions" : [ 110 ],
      "inTransitions" : []
    }
  ],
  "transitions" : [
    {
      "id" : 110,
      "name" : "Go2Nowhere",
      "inState" : 102,
      "outState" : 199,
      "preCondition" : null
    }
  ]
}
