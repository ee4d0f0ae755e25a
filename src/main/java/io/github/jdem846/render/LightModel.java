package io.github.jdem846.render;

/**
 * How the sun, the cast shadows and the light of the sky make a cell's brightness ({@link Compositor}). In both,
 * the brightness d in [−1, 1] then goes through the jDem846 tone and eq. 8 on the tint (−1 black, 0 the tint, +1
 * white); {@code dot} is the cosine of incidence from the hillshade, s the shadowed fraction, svf the sky-view
 * factor, W the scene's ambient (sky) weight and fade the twilight darkening.
 */
public enum LightModel {
    /**
     * The original's: d = dot − 2 × shadow intensity × s − fade; a cast shadow darkens by a fixed amount, whatever
     * light the sky gives. With an ambient weight W &gt; 0, d = (1 − W)·d + W·(2·svf − 1); with W = 0 exactly the
     * original.
     */
    JDEM846,
    /**
     * Sun and sky, as shaded-relief cartography lights terrain: the light L = max(0, dot) · (1 − s) + W · svf
     * (direct sun on the slope where it is not shadowed, plus the sky's light, W its strength relative to the sun's,
     * on the share of the sky the cell sees), and d = 2L − 1 − fade, so that L = ½ shows the tint itself and L ≥ 1
     * white. Without a hillshade, dot is that of level ground, sin(sun
     * elevation).
     */
    SKY;

    /** The ambient weight the command line gives {@link #SKY} unless told otherwise. */
    public static final double SKY_AMBIENT = 0.35;
}
