{
  "id" : 1800000000000,
  "name" : "Malformed",
  "states" : [ {
    "id" : 1800000000002,
    "name" : "Start"
  } 
  "transitions" : [ ]
}
