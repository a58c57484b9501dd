// Everything of the Action Flow Plan runtime; generated plan code includes this.
#pragma once

#include "afp/actor.h"
#include "afp/configuration.h"
#include "afp/context.h"
#include "afp/link_trace.h"
#include "afp/params.h"
#include "afp/plan.h"
#include "afp/status.h"
#include "afp/stepped_executor.h"
#include "afp/sub_plan.h"
#include "afp/supervisor.h"
#include "afp/threaded_executor.h"
#include "afp/trace.h"
#include "afp/value.h"
