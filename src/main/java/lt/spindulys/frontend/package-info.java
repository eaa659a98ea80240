/**
 * What the front ends (the command line and the viewer) share with each other and no library
 * user needs: the one line a user is shown for a failure. Not exported.
 */
package lt.spindulys.frontend;
