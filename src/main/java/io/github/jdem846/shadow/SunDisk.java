package io.github.jdem846.shadow;

/**
 * The sun as a uniform disk: the fraction hidden by a horizon at a given angle. The horizon is taken as a straight
 * horizontal edge across the disk, so the hidden part is a circular segment.
 */
final class SunDisk {

    private SunDisk() {
    }

    /**
     * Hidden fraction of a disk of angular radius {@code radiusDeg} centred at {@code elevationDeg}, behind a horizon
     * at {@code horizonDeg}; 1 when the horizon is above the upper limb, 0 when below the lower limb. A zero radius
     * gives the hard answer (1 when the horizon is above the centre).
     */
    static double hiddenFraction(double elevationDeg, double horizonDeg, double radiusDeg) {
        if (horizonDeg != horizonDeg) {
            return 0;
        }
        if (radiusDeg <= 0) {
            return horizonDeg > elevationDeg ? 1 : 0;
        }
        double u = (elevationDeg - horizonDeg) / radiusDeg;
        if (u >= 1) {
            return 0;
        }
        if (u <= -1) {
            return 1;
        }
        return (Math.acos(u) - u * Math.sqrt(1 - u * u)) / Math.PI;
    }
}
