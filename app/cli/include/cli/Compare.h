#pragma once
/// @file Compare.h
/// `rt compare A.png B.png [--diff OUT.png] [--tolerance T]`: how far two images of the same size
/// are apart, pixel by pixel, so that a student can check a render against a reference image
/// (docs/images/) exactly, or within a stated tolerance. The measures and the heat map are stage
/// 4's (camera/ImageDiff.h); the command reads the files, checks the options and prints.

#include "camera/ImageDiff.h"
