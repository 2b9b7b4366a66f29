"""Jobs for an arm: pick and place, stacking, drawing, music, search."""
