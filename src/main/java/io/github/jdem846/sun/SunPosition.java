package io.github.jdem846.sun;

import io.github.jdem846.light.LightDirection;

/**
 * The topocentric position of the sun's centre on the sky, refraction included: azimuth clockwise from north
 * (0 = north, 90 = east, 180 = south, 270 = west) and zenith angle from the vertical. The elevation is
 * 90° − zenith; it is negative at night.
 *
 * @param azimuthDegrees clockwise from north, in [0, 360)
 * @param zenithDegrees  from the vertical, in [0, 180]
 */
public record SunPosition(double azimuthDegrees, double zenithDegrees) {

    /**
     * Checks the ranges and brings the azimuth into [0, 360).
     *
     * @param azimuthDegrees clockwise from north, in [0, 360)
     * @param zenithDegrees from the vertical, in [0, 180]
     */
    public SunPosition {
        if (!Double.isFinite(azimuthDegrees)) {
            throw new IllegalArgumentException("sun azimuth must be finite, got " + azimuthDegrees);
        }
        if (!(zenithDegrees >= 0 && zenithDegrees <= 180)) {
            throw new IllegalArgumentException("sun zenith angle must be between 0 and 180 degrees, got "
                    + zenithDegrees);
        }
        azimuthDegrees = LightDirection.normalizeAzimuth(azimuthDegrees);
    }

    /** {@return elevation above the horizon, 90° − zenith, in [−90, 90]; negative when the sun is down} */
    public double elevationDegrees() {
        return 90 - zenithDegrees;
    }

    /** {@return true when the sun's centre is at or below the horizon: no direct light (as {@link LightDirection})} */
    public boolean isBelowHorizon() {
        return elevationDegrees() <= 0;
    }

    /**
     * The light for the renderer. The elevation is passed on as it is, negative below the horizon, so that
     * {@link LightDirection#isBelowHorizon()} tells the renderer that no cell gets direct light; the darkening of
     * twilight is {@link TwilightFade}'s job, from {@link #zenithDegrees()}.
     *
     * @return the azimuth and elevation as light coming from that direction
     */
    public LightDirection toLightDirection() {
        return new LightDirection(azimuthDegrees, elevationDegrees());
    }
}
