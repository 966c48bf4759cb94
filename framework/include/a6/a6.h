// Everything a student file may include: the API of the seven tasks.
#pragma once

#include "a6/cloth.h"
#include "a6/force_model.h"
#include "a6/forces.h"
#include "a6/implicit.h"
#include "a6/joints.h"
#include "a6/mass_spring_system.h"
#include "a6/particle.h"
#include "a6/particle_system.h"
#include "a6/random.h"
#include "a6/spring.h"
