"""Junction points of a known corridor, projected by hand with geometry.md's formulas
(sections 2 and 4), independently of the library."""

import math

import numpy as np

FX = FY = 500.0
CX, CY = 319.5, 239.5
WIDTH_PX, HEIGHT_PX = 640, 480
H = 1.2                                  # camera height, m
YAW, PITCH = 0.1, 0.08                   # phi, theta, rad
OFFSET, WIDTH = 0.3, 2.4                 # tau, w, m
D_LEFT, D_RIGHT = WIDTH / 2 + OFFSET, WIDTH / 2 - OFFSET
ALONG = np.linspace(3.0, 15.0, 12)       # s along the corridor, m


def rotation(yaw=YAW, pitch=PITCH):
    """R = R_x(theta) R_y(phi): P_C = R P_W."""
    cy, sy, cp, sp = math.cos(yaw), math.sin(yaw), math.cos(pitch), math.sin(pitch)
    r_y = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    r_x = np.array([[1, 0, 0], [0, cp, -sp], [0, sp, cp]])
    return r_x @ r_y


def camera_points(x_wall):
    """Camera-frame points of the junction X_W = x_wall, Y_W = h, Z_W = s."""
    world = np.stack([np.full_like(ALONG, x_wall), np.full_like(ALONG, H), ALONG], axis=1)
    return world @ rotation().T


def pixels(points):
    return np.stack([FX * points[:, 0] / points[:, 2] + CX,
                     FY * points[:, 1] / points[:, 2] + CY], axis=1)


LEFT_C = camera_points(-D_LEFT)
RIGHT_C = camera_points(D_RIGHT)
LEFT = pixels(LEFT_C)
RIGHT = pixels(RIGHT_C)
# Vanishing point K d, d = (sin phi, -sin theta cos phi, cos theta cos phi).
DIRECTION = np.array([math.sin(YAW), -math.sin(PITCH) * math.cos(YAW),
                      math.cos(PITCH) * math.cos(YAW)])
VANISHING_POINT = np.array([FX * DIRECTION[0] / DIRECTION[2] + CX,
                            FY * DIRECTION[1] / DIRECTION[2] + CY])
