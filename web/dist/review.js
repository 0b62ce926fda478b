/*! ergocell review page. Bundles three.js 0.187.0 and uPlot 1.6.32.

three.js:
The MIT License

Copyright © 2010-2026 three.js authors

Permission is hereby granted, free of charge, to any person obtaining a copy
of this software and associated documentation files (the "Software"), to deal
in the Software without restriction, including without limitation the rights
to use, copy, modify, merge, publish, distribute, sublicense, and/or sell
copies of the Software, and to permit persons to whom the Software is
furnished to do so, subject to the following conditions:

The above copyright notice and this permission notice shall be included in
all copies or substantial portions of the Software.

THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER
LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN
THE SOFTWARE.

uPlot:
The MIT License (MIT)

Copyright (c) 2022 Leon Sorokin

Permission is hereby granted, free of charge, to any person obtaining a copy
of this software and associated documentation files (the "Software"), to deal
in the Software without restriction, including without limitation the rights
to use, copy, modify, merge, publish, distribute, sublicense, and/or sell
copies of the Software, and to permit persons to whom the Software is
furnished to do so, subject to the following conditions:

The above copyright notice and this permission notice shall be included in
all copies or substantial portions of the Software.

THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER
LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN
THE SOFTWARE.
*/
(()=>{async function _f(){if(typeof window.ERGOCELL_REVIEW_DATA<"u")return window.ERGOCELL_REVIEW_DATA;if(location.protocol==="file:")throw new Error("this file holds no review data (write reports with `ergocell report`, or open the page `ergocell review` serves)");let i;try{i=await fetch("api/review.json",{cache:"no-store"})}catch(e){throw new Error(`could not reach the review server (${e.message})`)}if(!i.ok)throw new Error(`api/review.json answered ${i.status} ${i.statusText}`);try{return await i.json()}catch(e){throw new Error(`api/review.json is not valid JSON (${e.message})`)}}var Ft=i=>Array.isArray(i)?i:[],Xe=i=>typeof i=="number"&&Number.isFinite(i)?i:null;function mf(i,e){let t=Ft(i),n=new Uint8Array(e);for(let s=0;s<e;s++)n[s]=t[s]===!0?1:0;return n}function D0(i){let e=Ft(i).map(Xe).filter(t=>t!==null).sort((t,n)=>t-n);return e.filter((t,n)=>n===0||t!==e[n-1])}var ri=i=>i==null?"":String(i);function N0(i){return Ft(i).filter(e=>e&&Xe(e.t_start)!==null&&Xe(e.t_end)!==null).map(e=>({t_start:e.t_start,t_end:Math.max(e.t_start,e.t_end),planned_s:Xe(e.planned_s),leg:ri(e.leg),leg_id:Number.isInteger(e.leg_id)?e.leg_id:0,outcome:ri(e.outcome),end_known:e.end_known!==!1,feedback_count:Xe(e.feedback_count),max_error:Xe(e.max_error),text:ri(e.text)})).sort((e,t)=>e.t_start-t.t_start)}function U0(i){return Ft(i).filter(e=>e&&Xe(e.t)!==null&&e.kind!=="feedback").map(e=>({t:e.t,kind:ri(e.kind),leg:ri(e.leg),status:ri(e.status),error_code:Xe(e.error_code),text:ri(e.text),max_error:Xe(e.max_error)})).sort((e,t)=>e.t-t.t)}function F0(i){return Ft(i).filter(e=>e&&Xe(e.t)!==null).map(e=>({t:e.t,part:Xe(e.part),hand:e.hand==null?null:String(e.hand),distance_m:Xe(e.distance_m),reason:ri(e.reason)})).sort((e,t)=>e.t-t.t)}function Xa(i,e){let t=null;for(let n of i){if(n.t_start>e+1e-9)break;e<n.t_end&&(t=n)}return t}function gf(i,e){let t=Ft(i),n=new Array(e);for(let s=0;s<e;s++){let r=Array.isArray(t[s])?t[s]:[];n[s]=r.map(o=>{let a=Xe(o);return a!==null&&a>=0&&a<=1?a:null})}return n}function js(i,e){let t=Ft(i),n=new Array(e);for(let s=0;s<e;s++)n[s]=Xe(t[s]);return n}function xf(i,e){i=i||{};let t=i.frames||{},n=Ft(t.t),s=0;for(;s<n.length&&Xe(n[s])!==null;)s++;let r=Float64Array.from(n.slice(0,s)),o=Ft(i.landmarks).map(String),a=Ft(t.positions),c=o.length;if(!c){for(let b of a)if(Array.isArray(b)){c=Math.floor(b.length/3);break}}c||(c=33);let l=new Array(s),d=new Array(s),u=Ft(t.strain);for(let b=0;b<s;b++){let _=new Float64Array(c*3).fill(NaN),A=a[b];if(Array.isArray(A))for(let T=0;T<c;T++){let F=Xe(A[3*T]),B=Xe(A[3*T+1]),D=Xe(A[3*T+2]);F!==null&&B!==null&&D!==null&&(_[3*T]=F,_[3*T+1]=B,_[3*T+2]=D)}l[b]=_;let H=u[b],O=new Float64Array(c).fill(NaN);if(Array.isArray(H))for(let T=0;T<c;T++){let F=Xe(H[T]);F!==null&&(O[T]=F)}d[b]=O}let h=Ft(i.bones).filter(b=>Array.isArray(b)&&b.length===2&&b.every(_=>Number.isInteger(_)&&_>=0&&_<c)),m=Ft(i.up).map(Number),g=m.length===3&&m.every(Number.isFinite)?m:[0,0,1],v=Math.hypot(...g);g=v>0?g.map(b=>b/v):[0,0,1];let p=null,f=i.robot||{};if(f.tcp&&Array.isArray(f.tcp.t)){let b=[],_=[],A=Ft(f.tcp.positions);f.tcp.t.forEach((H,O)=>{let T=Ft(A[O]).map(Xe);Xe(H)!==null&&T.length===3&&T.every(F=>F!==null)&&(b.push(H),_.push(T))}),b.length&&(p={t:Float64Array.from(b),positions:_})}let y=Ft(f.handover_point).map(Xe),C=y.length===3&&y.every(b=>b!==null)?y:null,M=i.source||{},R=i.facts||{};return{index:e,label:String(i.label??M.file??`session ${e+1}`),source:{file:M.file??null,bytes:Xe(M.bytes),messages:Xe(M.messages),complete:M.complete!==!1,problems:Ft(M.problems).map(String)},facts:{height_m:Xe(R.height_m),height_uncertainty_m:Xe(R.height_uncertainty_m),height_class:R.height_class??null,decision_basis:R.decision_basis??null,class_probability:Xe(R.class_probability),expected_rula_cost:Xe(R.expected_rula_cost),trajectory_sha256:R.trajectory_sha256??null,approved_by:Ft(R.approved_by).map(String),states:Ft(R.states).filter(b=>b&&typeof b=="object")},partsTaken:F0(R.parts_taken),hasPartsTaken:Array.isArray(R.parts_taken),robotLegs:N0(f.legs),robotHolds:Ft(f.holds).map(Xe).filter(b=>b!==null).sort((b,_)=>b-_),robotEvents:U0(f.events),landmarks:o,nl:c,bones:h,up:g,n:s,t:r,positions:l,strain:d,grandLeft:js(t.grand_left,s),grandRight:js(t.grand_right,s),actionLeft:js(t.action_left,s),actionRight:js(t.action_right,s),actionLevel:js(t.action_level,s),rebaLeft:js(t.reba_left,s),rebaRight:js(t.reba_right,s),hasReba:Array.isArray(t.reba_left)&&t.reba_left.some(b=>b!=null),uncertainLeft:mf(t.uncertain_left,s),uncertainRight:mf(t.uncertain_right,s),hasUncertain:Array.isArray(t.uncertain_left)||Array.isArray(t.uncertain_right),bandLeft:gf(t.band_left,s),bandRight:gf(t.band_right,s),tcp:p,handover:C,warnings:Ft(i.warnings).filter(b=>b&&Xe(b.t)!==null).sort((b,_)=>b.t-_.t),regions:Ft(i.regions).filter(b=>b&&typeof b=="object"),summary:i.summary&&typeof i.summary=="object"?i.summary:{},angles:Ft(i.angles).filter(b=>b&&typeof b=="object").map(b=>({...b,score_edges_deg:D0(b.score_edges_deg)})),overview:B0(i.overview),findings:O0(i.findings)}}function O0(i){if(!i||typeof i!="object")return null;let e=Ft(i.action_level_secs).map(Xe);return e.length!==4||e.some(t=>t===null)?null:{action_level_secs:e,unscored_secs:Xe(i.unscored_secs)??0,dwell_s:Xe(i.dwell_s)??2,worst_moments:Ft(i.worst_moments).filter(t=>t&&Xe(t.t)!==null).map(t=>({t:t.t,action_level:Xe(t.action_level)??0,grand_left:Xe(t.grand_left),grand_right:Xe(t.grand_right),regions:Ft(t.regions).filter(n=>n&&typeof n=="object").map(n=>({region:ri(n.region),side:ri(n.side),score:Xe(n.score)}))})),regions:Ft(i.regions).filter(t=>t&&typeof t=="object").map(t=>({region:ri(t.region),side:ri(t.side),verdict:ri(t.verdict),warn_at:Xe(t.warn_at),highest:Xe(t.highest),top:Xe(t.top),share_at_warn:Xe(t.share_at_warn)??0,secs_at_warn:Xe(t.secs_at_warn)??0,episodes_at_warn:Xe(t.episodes_at_warn)??0,longest_at_warn_secs:Xe(t.longest_at_warn_secs)??0,warnings_raised:Xe(t.warnings_raised)??0,advice_text:t.advice_text==null?null:String(t.advice_text)}))}}function B0(i){if(!i||typeof i!="object")return null;let e=Xe(i.frames_recorded),t=Xe(i.frames_kept);if(e===null||t===null)return null;let n=Ft(i.windows).filter(s=>Array.isArray(s)&&s.length===2&&Xe(s[0])!==null&&Xe(s[1])!==null).map(s=>[Xe(s[0]),Xe(s[1])]);return{recorded:e,kept:t,bucketS:Xe(i.bucket_s)??0,windows:n}}function Uo(i,e){let t=i.length;if(!t||e<=i[0])return 0;if(e>=i[t-1])return t-1;let n=0,s=t-1;for(;s-n>1;){let r=n+s>>1;i[r]<=e?n=r:s=r}return e-i[n]<=i[s]-e?n:s}function Cr(i,e){let t=i.length;if(!t||e<i[0])return 0;let n=0,s=t;for(;s-n>1;){let r=n+s>>1;i[r]<=e?n=r:s=r}return n}var Hs={LEFT:0,MIDDLE:1,RIGHT:2,ROTATE:0,DOLLY:1,PAN:2},Gs={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},Jf=0,au=1,Kf=2;var va=1,jf=2,no=3,Ws=0,Yn=1,Zi=2,or=0,io=1,lu=2,cu=3,hu=4,Qf=5;var ar=100,ep=101,tp=102,np=103,ip=104,sp=200,rp=201,op=202,ap=203,uu=204,du=205,lp=206,cp=207,hp=208,up=209,dp=210,fp=211,pp=212,mp=213,gp=214,xl=0,vl=1,yl=2,Xr=3,bl=4,Sl=5,Ml=6,wl=7,fu=0,_p=1,xp=2,Ji=0,pu=1,mu=2,gu=3,_u=4,xu=5,vu=6,yu=7;var bu=300,lr=301,so=302,jl=303,Ql=304,El=1e3,qi=1001,Tl=1002,Tn=1003,vp=1004;var ya=1005;var Xn=1006,ec=1007;var ys=1008;var Qn=1009,Su=1010,Mu=1011,ro=1012,tc=1013,Li=1014,Di=1015,Ni=1016,nc=1017,ic=1018,cr=1020,wu=35902,Eu=35899,Tu=1021,Au=1022,Ui=1023,ms=1026,bs=1027,Ru=1028,sc=1029,$s=1030,rc=1031;var oc=1033,ba=33776,Sa=33777,Ma=33778,wa=33779,ac=35840,lc=35841,cc=35842,hc=35843,uc=36196,dc=37492,fc=37496,pc=37488,mc=37489,Ea=37490,gc=37491,_c=37808,xc=37809,vc=37810,yc=37811,bc=37812,Sc=37813,Mc=37814,wc=37815,Ec=37816,Tc=37817,Ac=37818,Rc=37819,Cc=37820,Pc=37821,Ic=36492,Lc=36494,Dc=36495,Nc=36283,Uc=36284,Ta=36285,Fc=36286;var Wo=2300,Al=2301,gl=2302,eu=2303,tu=2400,nu=2401,iu=2402;var yp=3200;var Oc=0,bp=1,Ss="",On="srgb",$o="srgb-linear",Xo="linear",Rt="srgb";var _l=7680;var Sp=519,Mp=512,wp=513,Ep=514,Cu=515,Tp=516,Ap=517,Pu=518,Iu=519,Lu=35044;var Du="300 es",vi=2e3,qr=2001;function k0(i){for(let e=i.length-1;e>=0;--e)if(i[e]>=65535)return!0;return!1}function z0(i){return ArrayBuffer.isView(i)&&!(i instanceof DataView)}function qo(i){return document.createElementNS("http://www.w3.org/1999/xhtml",i)}function Rp(){let i=qo("canvas");return i.style.display="block",i}var vf={},Yr=null;function Yo(...i){let e="THREE."+i.shift();Yr?Yr("log",e,...i):console.log(e,...i)}function Cp(i){let e=i[0];if(typeof e=="string"&&e.startsWith("TSL:")){let t=i[1];t&&t.isStackTrace?i[0]+=" "+t.getLocation():i[1]='Stack trace not available. Enable "THREE.Node.captureStackTrace" to capture stack traces.'}return i}function Ye(...i){i=Cp(i);let e="THREE."+i.shift();if(Yr)Yr("warn",e,...i);else{let t=i[0];t&&t.isStackTrace?console.warn(t.getError(e)):console.warn(e,...i)}}function it(...i){i=Cp(i);let e="THREE."+i.shift();if(Yr)Yr("error",e,...i);else{let t=i[0];t&&t.isStackTrace?console.error(t.getError(e)):console.error(e,...i)}}function Vo(...i){let e=i.join(" ");e in vf||(vf[e]=!0,Ye(...i))}function Pp(i,e,t){return new Promise(function(n,s){function r(){switch(i.clientWaitSync(e,i.SYNC_FLUSH_COMMANDS_BIT,0)){case i.WAIT_FAILED:s();break;case i.TIMEOUT_EXPIRED:setTimeout(r,t);break;default:n()}}setTimeout(r,t)})}var Ip={[xl]:xl,[yl]:Ml,[bl]:bl,[Xr]:Sl,[vl]:vl,[Ml]:yl,[wl]:wl,[Sl]:Xr},Ci=class{addEventListener(e,t){this._listeners===void 0&&(this._listeners={});let n=this._listeners;n[e]===void 0&&(n[e]=[]),n[e].indexOf(t)===-1&&n[e].push(t)}hasEventListener(e,t){let n=this._listeners;return n===void 0?!1:n[e]!==void 0&&n[e].indexOf(t)!==-1}removeEventListener(e,t){let n=this._listeners;if(n===void 0)return;let s=n[e];if(s!==void 0){let r=s.indexOf(t);r!==-1&&s.splice(r,1)}}dispatchEvent(e){let t=this._listeners;if(t===void 0)return;let n=t[e.type];if(n!==void 0){e.target=this;let s=n.slice(0);for(let r=0,o=s.length;r<o;r++)s[r].call(this,e);e.target=null}}},Un=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],yf=1234567,Ho=Math.PI/180,Zr=180/Math.PI;function Xs(){let i=Math.random()*4294967295|0,e=Math.random()*4294967295|0,t=Math.random()*4294967295|0,n=Math.random()*4294967295|0;return(Un[i&255]+Un[i>>8&255]+Un[i>>16&255]+Un[i>>24&255]+"-"+Un[e&255]+Un[e>>8&255]+"-"+Un[e>>16&15|64]+Un[e>>24&255]+"-"+Un[t&63|128]+Un[t>>8&255]+"-"+Un[t>>16&255]+Un[t>>24&255]+Un[n&255]+Un[n>>8&255]+Un[n>>16&255]+Un[n>>24&255]).toLowerCase()}function lt(i,e,t){return Math.max(e,Math.min(t,i))}function Nu(i,e){return(i%e+e)%e}function V0(i,e,t,n,s){return n+(i-e)*(s-n)/(t-e)}function H0(i,e,t){return i!==e?(t-i)/(e-i):0}function Go(i,e,t){return(1-t)*i+t*e}function G0(i,e,t,n){return Go(i,e,1-Math.exp(-t*n))}function W0(i,e=1){return e-Math.abs(Nu(i,e*2)-e)}function $0(i,e,t){return i<=e?0:i>=t?1:(i=(i-e)/(t-e),i*i*(3-2*i))}function X0(i,e,t){return i<=e?0:i>=t?1:(i=(i-e)/(t-e),i*i*i*(i*(i*6-15)+10))}function q0(i,e){return i+Math.floor(Math.random()*(e-i+1))}function Y0(i,e){return i+Math.random()*(e-i)}function Z0(i){return i*(.5-Math.random())}function J0(i){i!==void 0&&(yf=i);let e=yf+=1831565813;return e=Math.imul(e^e>>>15,e|1),e^=e+Math.imul(e^e>>>7,e|61),((e^e>>>14)>>>0)/4294967296}function K0(i){return i*Ho}function j0(i){return i*Zr}function Q0(i){return i>0&&Number.isInteger(i)&&2**Math.round(Math.log2(i))===i}function e_(i){return Math.pow(2,Math.ceil(Math.log(i)/Math.LN2))}function Uu(i){return Math.pow(2,Math.floor(Math.log(i)/Math.LN2))}function t_(i,e,t,n,s){let r=Math.cos,o=Math.sin,a=r(t/2),c=o(t/2),l=r((e+n)/2),d=o((e+n)/2),u=r((e-n)/2),h=o((e-n)/2),m=r((n-e)/2),g=o((n-e)/2);switch(s){case"XYX":i.set(a*d,c*u,c*h,a*l);break;case"YZY":i.set(c*h,a*d,c*u,a*l);break;case"ZXZ":i.set(c*u,c*h,a*d,a*l);break;case"XZX":i.set(a*d,c*g,c*m,a*l);break;case"YXY":i.set(c*m,a*d,c*g,a*l);break;case"ZYZ":i.set(c*g,c*m,a*d,a*l);break;default:Ye("MathUtils: .setQuaternionFromProperEuler() encountered an unknown order: "+s)}}function Bc(i){switch(i.constructor){case Uint32Array:return 4294967295;case Uint16Array:return 65535;case Uint8Array:case Uint8ClampedArray:return 255;case Int32Array:return 2147483647;case Int16Array:return 32767;case Int8Array:return 127;default:return}}function Fu(i,e){if(e.constructor===Float32Array)return i;let t=Bc(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.max(i/t,-1)}function Ou(i,e){if(e.constructor===Float32Array)return i;let t=Bc(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.round(i*t)}var Aa={DEG2RAD:Ho,RAD2DEG:Zr,generateUUID:Xs,clamp:lt,euclideanModulo:Nu,mapLinear:V0,inverseLerp:H0,lerp:Go,damp:G0,pingpong:W0,smoothstep:$0,smootherstep:X0,randInt:q0,randFloat:Y0,randFloatSpread:Z0,seededRandom:J0,degToRad:K0,radToDeg:j0,isPowerOfTwo:Q0,ceilPowerOfTwo:e_,floorPowerOfTwo:Uu,setQuaternionFromProperEuler:t_,normalize:Ou,denormalize:Fu},Hu=class Hu{constructor(e=0,t=0){this.x=e,this.y=t}get width(){return this.x}set width(e){this.x=e}get height(){return this.y}set height(e){this.y=e}set(e,t){return this.x=e,this.y=t,this}setScalar(e){return this.x=e,this.y=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;default:throw new Error("THREE.Vector2: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;default:throw new Error("THREE.Vector2: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y)}copy(e){return this.x=e.x,this.y=e.y,this}add(e){return this.x+=e.x,this.y+=e.y,this}addScalar(e){return this.x+=e,this.y+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this}subScalar(e){return this.x-=e,this.y-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this}multiply(e){return this.x*=e.x,this.y*=e.y,this}multiplyScalar(e){return this.x*=e,this.y*=e,this}divide(e){return this.x/=e.x,this.y/=e.y,this}divideScalar(e){return this.multiplyScalar(1/e)}applyMatrix3(e){let t=this.x,n=this.y,s=e.elements;return this.x=s[0]*t+s[3]*n+s[6],this.y=s[1]*t+s[4]*n+s[7],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this}clamp(e,t){return this.x=lt(this.x,e.x,t.x),this.y=lt(this.y,e.y,t.y),this}clampScalar(e,t){return this.x=lt(this.x,e,t),this.y=lt(this.y,e,t),this}clampLength(e,t){let n=this.length();return this.divideScalar(n||1).multiplyScalar(lt(n,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(e){return this.x*e.x+this.y*e.y}cross(e){return this.x*e.y-this.y*e.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(e){let t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;let n=this.dot(e)/t;return Math.acos(lt(n,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){let t=this.x-e.x,n=this.y-e.y;return t*t+n*n}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this}lerpVectors(e,t,n){return this.x=e.x+(t.x-e.x)*n,this.y=e.y+(t.y-e.y)*n,this}equals(e){return e.x===this.x&&e.y===this.y}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this}rotateAround(e,t){let n=Math.cos(t),s=Math.sin(t),r=this.x-e.x,o=this.y-e.y;return this.x=r*n-o*s+e.x,this.y=r*s+o*n+e.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}};Hu.prototype.isVector2=!0;var je=Hu,ci=class{constructor(e=0,t=0,n=0,s=1){this.isQuaternion=!0,this._x=e,this._y=t,this._z=n,this._w=s}static slerpFlat(e,t,n,s,r,o,a){let c=n[s+0],l=n[s+1],d=n[s+2],u=n[s+3],h=r[o+0],m=r[o+1],g=r[o+2],v=r[o+3];if(u!==v||c!==h||l!==m||d!==g){let p=c*h+l*m+d*g+u*v;p<0&&(h=-h,m=-m,g=-g,v=-v,p=-p);let f=1-a;if(p<.9995){let y=Math.acos(p),C=Math.sin(y);f=Math.sin(f*y)/C,a=Math.sin(a*y)/C,c=c*f+h*a,l=l*f+m*a,d=d*f+g*a,u=u*f+v*a}else{c=c*f+h*a,l=l*f+m*a,d=d*f+g*a,u=u*f+v*a;let y=1/Math.sqrt(c*c+l*l+d*d+u*u);c*=y,l*=y,d*=y,u*=y}}e[t]=c,e[t+1]=l,e[t+2]=d,e[t+3]=u}static multiplyQuaternionsFlat(e,t,n,s,r,o){let a=n[s],c=n[s+1],l=n[s+2],d=n[s+3],u=r[o],h=r[o+1],m=r[o+2],g=r[o+3];return e[t]=a*g+d*u+c*m-l*h,e[t+1]=c*g+d*h+l*u-a*m,e[t+2]=l*g+d*m+a*h-c*u,e[t+3]=d*g-a*u-c*h-l*m,e}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get w(){return this._w}set w(e){this._w=e,this._onChangeCallback()}set(e,t,n,s){return this._x=e,this._y=t,this._z=n,this._w=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(e){return this._x=e.x,this._y=e.y,this._z=e.z,this._w=e.w,this._onChangeCallback(),this}setFromEuler(e,t=!0){let n=e._x,s=e._y,r=e._z,o=e._order,a=Math.cos,c=Math.sin,l=a(n/2),d=a(s/2),u=a(r/2),h=c(n/2),m=c(s/2),g=c(r/2);switch(o){case"XYZ":this._x=h*d*u+l*m*g,this._y=l*m*u-h*d*g,this._z=l*d*g+h*m*u,this._w=l*d*u-h*m*g;break;case"YXZ":this._x=h*d*u+l*m*g,this._y=l*m*u-h*d*g,this._z=l*d*g-h*m*u,this._w=l*d*u+h*m*g;break;case"ZXY":this._x=h*d*u-l*m*g,this._y=l*m*u+h*d*g,this._z=l*d*g+h*m*u,this._w=l*d*u-h*m*g;break;case"ZYX":this._x=h*d*u-l*m*g,this._y=l*m*u+h*d*g,this._z=l*d*g-h*m*u,this._w=l*d*u+h*m*g;break;case"YZX":this._x=h*d*u+l*m*g,this._y=l*m*u+h*d*g,this._z=l*d*g-h*m*u,this._w=l*d*u-h*m*g;break;case"XZY":this._x=h*d*u-l*m*g,this._y=l*m*u-h*d*g,this._z=l*d*g+h*m*u,this._w=l*d*u+h*m*g;break;default:Ye("Quaternion: .setFromEuler() encountered an unknown order: "+o)}return t===!0&&this._onChangeCallback(),this}setFromAxisAngle(e,t){let n=t/2,s=Math.sin(n);return this._x=e.x*s,this._y=e.y*s,this._z=e.z*s,this._w=Math.cos(n),this._onChangeCallback(),this}setFromRotationMatrix(e){let t=e.elements,n=t[0],s=t[4],r=t[8],o=t[1],a=t[5],c=t[9],l=t[2],d=t[6],u=t[10],h=n+a+u;if(h>0){let m=.5/Math.sqrt(h+1);this._w=.25/m,this._x=(d-c)*m,this._y=(r-l)*m,this._z=(o-s)*m}else if(n>a&&n>u){let m=2*Math.sqrt(1+n-a-u);this._w=(d-c)/m,this._x=.25*m,this._y=(s+o)/m,this._z=(r+l)/m}else if(a>u){let m=2*Math.sqrt(1+a-n-u);this._w=(r-l)/m,this._x=(s+o)/m,this._y=.25*m,this._z=(c+d)/m}else{let m=2*Math.sqrt(1+u-n-a);this._w=(o-s)/m,this._x=(r+l)/m,this._y=(c+d)/m,this._z=.25*m}return this._onChangeCallback(),this}setFromUnitVectors(e,t){let n=e.dot(t)+1;return n<1e-8?(n=0,Math.abs(e.x)>Math.abs(e.z)?(this._x=-e.y,this._y=e.x,this._z=0,this._w=n):(this._x=0,this._y=-e.z,this._z=e.y,this._w=n)):(this._x=e.y*t.z-e.z*t.y,this._y=e.z*t.x-e.x*t.z,this._z=e.x*t.y-e.y*t.x,this._w=n),this.normalize()}angleTo(e){return 2*Math.acos(Math.abs(lt(this.dot(e),-1,1)))}rotateTowards(e,t){let n=this.angleTo(e);if(n===0)return this;let s=Math.min(1,t/n);return this.slerp(e,s),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(e){return this._x*e._x+this._y*e._y+this._z*e._z+this._w*e._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let e=this.length();return e===0?(this._x=0,this._y=0,this._z=0,this._w=1):(e=1/e,this._x=this._x*e,this._y=this._y*e,this._z=this._z*e,this._w=this._w*e),this._onChangeCallback(),this}multiply(e){return this.multiplyQuaternions(this,e)}premultiply(e){return this.multiplyQuaternions(e,this)}multiplyQuaternions(e,t){let n=e._x,s=e._y,r=e._z,o=e._w,a=t._x,c=t._y,l=t._z,d=t._w;return this._x=n*d+o*a+s*l-r*c,this._y=s*d+o*c+r*a-n*l,this._z=r*d+o*l+n*c-s*a,this._w=o*d-n*a-s*c-r*l,this._onChangeCallback(),this}slerp(e,t){let n=e._x,s=e._y,r=e._z,o=e._w,a=this.dot(e);a<0&&(n=-n,s=-s,r=-r,o=-o,a=-a);let c=1-t;if(a<.9995){let l=Math.acos(a),d=Math.sin(l);c=Math.sin(c*l)/d,t=Math.sin(t*l)/d,this._x=this._x*c+n*t,this._y=this._y*c+s*t,this._z=this._z*c+r*t,this._w=this._w*c+o*t,this._onChangeCallback()}else this._x=this._x*c+n*t,this._y=this._y*c+s*t,this._z=this._z*c+r*t,this._w=this._w*c+o*t,this.normalize();return this}slerpQuaternions(e,t,n){return this.copy(e).slerp(t,n)}random(){let e=2*Math.PI*Math.random(),t=2*Math.PI*Math.random(),n=Math.random(),s=Math.sqrt(1-n),r=Math.sqrt(n);return this.set(s*Math.sin(e),s*Math.cos(e),r*Math.sin(t),r*Math.cos(t))}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._w===this._w}fromArray(e,t=0){return this._x=e[t],this._y=e[t+1],this._z=e[t+2],this._w=e[t+3],this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._w,e}fromBufferAttribute(e,t){return this._x=e.getX(t),this._y=e.getY(t),this._z=e.getZ(t),this._w=e.getW(t),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}},Gu=class Gu{constructor(e=0,t=0,n=0){this.x=e,this.y=t,this.z=n}set(e,t,n){return n===void 0&&(n=this.z),this.x=e,this.y=t,this.z=n,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;default:throw new Error("THREE.Vector3: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("THREE.Vector3: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this}multiplyVectors(e,t){return this.x=e.x*t.x,this.y=e.y*t.y,this.z=e.z*t.z,this}applyEuler(e){return this.applyQuaternion(bf.setFromEuler(e))}applyAxisAngle(e,t){return this.applyQuaternion(bf.setFromAxisAngle(e,t))}applyMatrix3(e){let t=this.x,n=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[3]*n+r[6]*s,this.y=r[1]*t+r[4]*n+r[7]*s,this.z=r[2]*t+r[5]*n+r[8]*s,this}applyNormalMatrix(e){return this.applyMatrix3(e).normalize()}applyMatrix4(e){let t=this.x,n=this.y,s=this.z,r=e.elements,o=1/(r[3]*t+r[7]*n+r[11]*s+r[15]);return this.x=(r[0]*t+r[4]*n+r[8]*s+r[12])*o,this.y=(r[1]*t+r[5]*n+r[9]*s+r[13])*o,this.z=(r[2]*t+r[6]*n+r[10]*s+r[14])*o,this}applyQuaternion(e){let t=this.x,n=this.y,s=this.z,r=e.x,o=e.y,a=e.z,c=e.w,l=2*(o*s-a*n),d=2*(a*t-r*s),u=2*(r*n-o*t);return this.x=t+c*l+o*u-a*d,this.y=n+c*d+a*l-r*u,this.z=s+c*u+r*d-o*l,this}project(e){return this.applyMatrix4(e.matrixWorldInverse).applyMatrix4(e.projectionMatrix)}unproject(e){return this.applyMatrix4(e.projectionMatrixInverse).applyMatrix4(e.matrixWorld)}transformDirection(e){let t=this.x,n=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[4]*n+r[8]*s,this.y=r[1]*t+r[5]*n+r[9]*s,this.z=r[2]*t+r[6]*n+r[10]*s,this.normalize()}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this}divideScalar(e){return this.multiplyScalar(1/e)}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this}clamp(e,t){return this.x=lt(this.x,e.x,t.x),this.y=lt(this.y,e.y,t.y),this.z=lt(this.z,e.z,t.z),this}clampScalar(e,t){return this.x=lt(this.x,e,t),this.y=lt(this.y,e,t),this.z=lt(this.z,e,t),this}clampLength(e,t){let n=this.length();return this.divideScalar(n||1).multiplyScalar(lt(n,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this}lerpVectors(e,t,n){return this.x=e.x+(t.x-e.x)*n,this.y=e.y+(t.y-e.y)*n,this.z=e.z+(t.z-e.z)*n,this}cross(e){return this.crossVectors(this,e)}crossVectors(e,t){let n=e.x,s=e.y,r=e.z,o=t.x,a=t.y,c=t.z;return this.x=s*c-r*a,this.y=r*o-n*c,this.z=n*a-s*o,this}projectOnVector(e){let t=e.lengthSq();if(t===0)return this.set(0,0,0);let n=e.dot(this)/t;return this.copy(e).multiplyScalar(n)}projectOnPlane(e){return Lh.copy(this).projectOnVector(e),this.sub(Lh)}reflect(e){return this.sub(Lh.copy(e).multiplyScalar(2*this.dot(e)))}angleTo(e){let t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;let n=this.dot(e)/t;return Math.acos(lt(n,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){let t=this.x-e.x,n=this.y-e.y,s=this.z-e.z;return t*t+n*n+s*s}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)+Math.abs(this.z-e.z)}setFromSpherical(e){return this.setFromSphericalCoords(e.radius,e.phi,e.theta)}setFromSphericalCoords(e,t,n){let s=Math.sin(t)*e;return this.x=s*Math.sin(n),this.y=Math.cos(t)*e,this.z=s*Math.cos(n),this}setFromCylindrical(e){return this.setFromCylindricalCoords(e.radius,e.theta,e.y)}setFromCylindricalCoords(e,t,n){return this.x=e*Math.sin(t),this.y=n,this.z=e*Math.cos(t),this}setFromMatrixPosition(e){let t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this}setFromMatrixScale(e){let t=this.setFromMatrixColumn(e,0).length(),n=this.setFromMatrixColumn(e,1).length(),s=this.setFromMatrixColumn(e,2).length();return this.x=t,this.y=n,this.z=s,this}setFromMatrixColumn(e,t){return this.fromArray(e.elements,t*4)}setFromMatrix3Column(e,t){return this.fromArray(e.elements,t*3)}setFromEuler(e){return this.x=e._x,this.y=e._y,this.z=e._z,this}setFromColor(e){return this.x=e.r,this.y=e.g,this.z=e.b,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){let e=Math.random()*Math.PI*2,t=Math.random()*2-1,n=Math.sqrt(1-t*t);return this.x=n*Math.cos(e),this.y=t,this.z=n*Math.sin(e),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}};Gu.prototype.isVector3=!0;var W=Gu,Lh=new W,bf=new ci,Wu=class Wu{constructor(e,t,n,s,r,o,a,c,l){this.elements=[1,0,0,0,1,0,0,0,1],e!==void 0&&this.set(e,t,n,s,r,o,a,c,l)}set(e,t,n,s,r,o,a,c,l){let d=this.elements;return d[0]=e,d[1]=s,d[2]=a,d[3]=t,d[4]=r,d[5]=c,d[6]=n,d[7]=o,d[8]=l,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(e){let t=this.elements,n=e.elements;return t[0]=n[0],t[1]=n[1],t[2]=n[2],t[3]=n[3],t[4]=n[4],t[5]=n[5],t[6]=n[6],t[7]=n[7],t[8]=n[8],this}extractBasis(e,t,n){return e.setFromMatrix3Column(this,0),t.setFromMatrix3Column(this,1),n.setFromMatrix3Column(this,2),this}setFromMatrix4(e){let t=e.elements;return this.set(t[0],t[4],t[8],t[1],t[5],t[9],t[2],t[6],t[10]),this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){let n=e.elements,s=t.elements,r=this.elements,o=n[0],a=n[3],c=n[6],l=n[1],d=n[4],u=n[7],h=n[2],m=n[5],g=n[8],v=s[0],p=s[3],f=s[6],y=s[1],C=s[4],M=s[7],R=s[2],b=s[5],_=s[8];return r[0]=o*v+a*y+c*R,r[3]=o*p+a*C+c*b,r[6]=o*f+a*M+c*_,r[1]=l*v+d*y+u*R,r[4]=l*p+d*C+u*b,r[7]=l*f+d*M+u*_,r[2]=h*v+m*y+g*R,r[5]=h*p+m*C+g*b,r[8]=h*f+m*M+g*_,this}multiplyScalar(e){let t=this.elements;return t[0]*=e,t[3]*=e,t[6]*=e,t[1]*=e,t[4]*=e,t[7]*=e,t[2]*=e,t[5]*=e,t[8]*=e,this}determinant(){let e=this.elements,t=e[0],n=e[1],s=e[2],r=e[3],o=e[4],a=e[5],c=e[6],l=e[7],d=e[8];return t*o*d-t*a*l-n*r*d+n*a*c+s*r*l-s*o*c}invert(){let e=this.elements,t=e[0],n=e[1],s=e[2],r=e[3],o=e[4],a=e[5],c=e[6],l=e[7],d=e[8],u=d*o-a*l,h=a*c-d*r,m=l*r-o*c,g=t*u+n*h+s*m;if(g===0)return this.set(0,0,0,0,0,0,0,0,0);let v=1/g;return e[0]=u*v,e[1]=(s*l-d*n)*v,e[2]=(a*n-s*o)*v,e[3]=h*v,e[4]=(d*t-s*c)*v,e[5]=(s*r-a*t)*v,e[6]=m*v,e[7]=(n*c-l*t)*v,e[8]=(o*t-n*r)*v,this}transpose(){let e,t=this.elements;return e=t[1],t[1]=t[3],t[3]=e,e=t[2],t[2]=t[6],t[6]=e,e=t[5],t[5]=t[7],t[7]=e,this}getNormalMatrix(e){return this.setFromMatrix4(e).invert().transpose()}transposeIntoArray(e){let t=this.elements;return e[0]=t[0],e[1]=t[3],e[2]=t[6],e[3]=t[1],e[4]=t[4],e[5]=t[7],e[6]=t[2],e[7]=t[5],e[8]=t[8],this}setUvTransform(e,t,n,s,r,o,a){let c=Math.cos(r),l=Math.sin(r);return this.set(n*c,n*l,-n*(c*o+l*a)+o+e,-s*l,s*c,-s*(-l*o+c*a)+a+t,0,0,1),this}scale(e,t){return Vo("Matrix3: .scale() is deprecated. Use .makeScale() instead."),this.premultiply(Dh.makeScale(e,t)),this}rotate(e){return Vo("Matrix3: .rotate() is deprecated. Use .makeRotation() instead."),this.premultiply(Dh.makeRotation(-e)),this}translate(e,t){return Vo("Matrix3: .translate() is deprecated. Use .makeTranslation() instead."),this.premultiply(Dh.makeTranslation(e,t)),this}makeTranslation(e,t){return e.isVector2?this.set(1,0,e.x,0,1,e.y,0,0,1):this.set(1,0,e,0,1,t,0,0,1),this}makeRotation(e){let t=Math.cos(e),n=Math.sin(e);return this.set(t,-n,0,n,t,0,0,0,1),this}makeScale(e,t){return this.set(e,0,0,0,t,0,0,0,1),this}equals(e){let t=this.elements,n=e.elements;for(let s=0;s<9;s++)if(t[s]!==n[s])return!1;return!0}fromArray(e,t=0){for(let n=0;n<9;n++)this.elements[n]=e[n+t];return this}toArray(e=[],t=0){let n=this.elements;return e[t]=n[0],e[t+1]=n[1],e[t+2]=n[2],e[t+3]=n[3],e[t+4]=n[4],e[t+5]=n[5],e[t+6]=n[6],e[t+7]=n[7],e[t+8]=n[8],e}clone(){return new this.constructor().fromArray(this.elements)}};Wu.prototype.isMatrix3=!0;var st=Wu,Dh=new st,Sf=new st().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),Mf=new st().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);function n_(){let i={enabled:!0,workingColorSpace:$o,spaces:{},convert:function(s,r,o){return this.enabled===!1||r===o||!r||!o||(this.spaces[r].transfer===Rt&&(s.r=ps(s.r),s.g=ps(s.g),s.b=ps(s.b)),this.spaces[r].primaries!==this.spaces[o].primaries&&(s.applyMatrix3(this.spaces[r].toXYZ),s.applyMatrix3(this.spaces[o].fromXYZ)),this.spaces[o].transfer===Rt&&(s.r=$r(s.r),s.g=$r(s.g),s.b=$r(s.b))),s},workingToColorSpace:function(s,r){return this.convert(s,this.workingColorSpace,r)},colorSpaceToWorking:function(s,r){return this.convert(s,r,this.workingColorSpace)},getPrimaries:function(s){return this.spaces[s].primaries},getTransfer:function(s){return s===Ss?Xo:this.spaces[s].transfer},getToneMappingMode:function(s){return this.spaces[s].outputColorSpaceConfig.toneMappingMode||"standard"},getLuminanceCoefficients:function(s,r=this.workingColorSpace){return s.fromArray(this.spaces[r].luminanceCoefficients)},define:function(s){Object.assign(this.spaces,s)},_getMatrix:function(s,r,o){return s.copy(this.spaces[o].fromXYZ).multiply(this.spaces[r].toXYZ)},_getDrawingBufferColorSpace:function(s){return this.spaces[s].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(s=this.workingColorSpace){return this.spaces[s].workingColorSpaceConfig.unpackColorSpace}},e=[.64,.33,.3,.6,.15,.06],t=[.2126,.7152,.0722],n=[.3127,.329];return i.define({[$o]:{primaries:e,whitePoint:n,transfer:Xo,toXYZ:Sf,fromXYZ:Mf,luminanceCoefficients:t,workingColorSpaceConfig:{unpackColorSpace:On},outputColorSpaceConfig:{drawingBufferColorSpace:On}},[On]:{primaries:e,whitePoint:n,transfer:Rt,toXYZ:Sf,fromXYZ:Mf,luminanceCoefficients:t,outputColorSpaceConfig:{drawingBufferColorSpace:On}}}),i}var _t=n_();function ps(i){return i<.04045?i*.0773993808:Math.pow(i*.9478672986+.0521327014,2.4)}function $r(i){return i<.0031308?i*12.92:1.055*Math.pow(i,.41666)-.055}var Pr,Rl=class{static getDataURL(e,t="image/png"){if(/^data:/i.test(e.src)||typeof HTMLCanvasElement>"u")return e.src;let n;if(e instanceof HTMLCanvasElement)n=e;else{Pr===void 0&&(Pr=qo("canvas")),Pr.width=e.width,Pr.height=e.height;let s=Pr.getContext("2d");e instanceof ImageData?s.putImageData(e,0,0):s.drawImage(e,0,0,e.width,e.height),n=Pr}return n.toDataURL(t)}static sRGBToLinear(e){if(typeof HTMLImageElement<"u"&&e instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&e instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&e instanceof ImageBitmap){let t=qo("canvas");t.width=e.width,t.height=e.height;let n=t.getContext("2d");n.drawImage(e,0,0,e.width,e.height);let s=n.getImageData(0,0,e.width,e.height),r=s.data;for(let o=0;o<r.length;o++)r[o]=ps(r[o]/255)*255;return n.putImageData(s,0,0),t}else if(e.data){let t=e.data.slice(0);for(let n=0;n<t.length;n++)t instanceof Uint8Array||t instanceof Uint8ClampedArray?t[n]=Math.floor(ps(t[n]/255)*255):t[n]=ps(t[n]);return{data:t,width:e.width,height:e.height}}else return Ye("ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),e}},i_=0,Jr=class{constructor(e=null){this.isTextureSource=!0,Object.defineProperty(this,"id",{value:i_++}),this.uuid=Xs(),this.data=e,this.dataReady=!0,this.version=0}getSize(e){let t=this.data;return typeof HTMLVideoElement<"u"&&t instanceof HTMLVideoElement?e.set(t.videoWidth,t.videoHeight,0):typeof VideoFrame<"u"&&t instanceof VideoFrame?e.set(t.displayWidth,t.displayHeight,0):t!==null?e.set(t.width||0,t.height||0,t.depth||0):e.set(0,0,0),e}set needsUpdate(e){e===!0&&this.version++}toJSON(e){let t=e===void 0||typeof e=="string";if(!t&&e.images[this.uuid]!==void 0)return e.images[this.uuid];let n={uuid:this.uuid,url:""},s=this.data;if(s!==null){let r;if(Array.isArray(s)){r=[];for(let o=0,a=s.length;o<a;o++)s[o].isDataTexture?r.push(Nh(s[o].image)):r.push(Nh(s[o]))}else r=Nh(s);n.url=r}return t||(e.images[this.uuid]=n),n}};function Nh(i){return typeof HTMLImageElement<"u"&&i instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&i instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&i instanceof ImageBitmap?Rl.getDataURL(i):i.data?{data:Array.from(i.data),width:i.width,height:i.height,type:i.data.constructor.name}:(Ye("Texture: Unable to serialize Texture."),{})}var s_=0,Uh=new W,jn=class i extends Ci{constructor(e=i.DEFAULT_IMAGE,t=i.DEFAULT_MAPPING,n=qi,s=qi,r=Xn,o=ys,a=Ui,c=Qn,l=i.DEFAULT_ANISOTROPY,d=Ss){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:s_++}),this.uuid=Xs(),this.name="",this.source=new Jr(e),this.mipmaps=[],this.mapping=t,this.channel=0,this.wrapS=n,this.wrapT=s,this.magFilter=r,this.minFilter=o,this.anisotropy=l,this.format=a,this.internalFormat=null,this.type=c,this.offset=new je(0,0),this.repeat=new je(1,1),this.center=new je(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new st,this.generateMipmaps=!0,this.mipmapsAutoUpdate=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=d,this.userData={},this.updateRanges=[],this.version=0,this.onUpdate=null,this.renderTarget=null,this.isRenderTargetTexture=!1,this.isArrayTexture=!!(e&&e.depth&&e.depth>1),this.pmremVersion=0,this.isPMREMTexture=!1,this.normalized=!1}get width(){return this.source.getSize(Uh).x}get height(){return this.source.getSize(Uh).y}get depth(){return this.source.getSize(Uh).z}get image(){return this.source.data}set image(e){this.source.data=e}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}clone(){return new this.constructor().copy(this)}copy(e){return this.name=e.name,this.source=e.source,this.mipmaps=e.mipmaps.slice(0),this.mapping=e.mapping,this.channel=e.channel,this.wrapS=e.wrapS,this.wrapT=e.wrapT,this.magFilter=e.magFilter,this.minFilter=e.minFilter,this.anisotropy=e.anisotropy,this.format=e.format,this.internalFormat=e.internalFormat,this.type=e.type,this.normalized=e.normalized,this.offset.copy(e.offset),this.repeat.copy(e.repeat),this.center.copy(e.center),this.rotation=e.rotation,this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrix.copy(e.matrix),this.generateMipmaps=e.generateMipmaps,this.mipmapsAutoUpdate=e.mipmapsAutoUpdate,this.premultiplyAlpha=e.premultiplyAlpha,this.flipY=e.flipY,this.unpackAlignment=e.unpackAlignment,this.colorSpace=e.colorSpace,this.renderTarget=e.renderTarget,this.isRenderTargetTexture=e.isRenderTargetTexture,this.isPMREMTexture=e.isPMREMTexture,this.isArrayTexture=e.isArrayTexture,this.userData=JSON.parse(JSON.stringify(e.userData)),this.needsUpdate=!0,this}setValues(e){for(let t in e){let n=e[t];if(n===void 0){Ye(`Texture.setValues(): parameter '${t}' has value of undefined.`);continue}let s=this[t];if(s===void 0){Ye(`Texture.setValues(): property '${t}' does not exist.`);continue}s&&n&&s.isVector2&&n.isVector2||s&&n&&s.isVector3&&n.isVector3||s&&n&&s.isMatrix3&&n.isMatrix3?s.copy(n):this[t]=n}}toJSON(e){let t=e===void 0||typeof e=="string";if(!t&&e.textures[this.uuid]!==void 0)return e.textures[this.uuid];let n={metadata:{version:4.7,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(e).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,normalized:this.normalized,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,mipmapsAutoUpdate:this.mipmapsAutoUpdate,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(n.userData=this.userData),t||(e.textures[this.uuid]=n),n}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(e){if(this.mapping!==bu)return e;if(e.applyMatrix3(this.matrix),e.x<0||e.x>1)switch(this.wrapS){case El:e.x=e.x-Math.floor(e.x);break;case qi:e.x=e.x<0?0:1;break;case Tl:Math.abs(Math.floor(e.x)%2)===1?e.x=Math.ceil(e.x)-e.x:e.x=e.x-Math.floor(e.x);break}if(e.y<0||e.y>1)switch(this.wrapT){case El:e.y=e.y-Math.floor(e.y);break;case qi:e.y=e.y<0?0:1;break;case Tl:Math.abs(Math.floor(e.y)%2)===1?e.y=Math.ceil(e.y)-e.y:e.y=e.y-Math.floor(e.y);break}return this.flipY&&(e.y=1-e.y),e}set needsUpdate(e){e===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(e){e===!0&&this.pmremVersion++}};jn.DEFAULT_IMAGE=null;jn.DEFAULT_MAPPING=bu;jn.DEFAULT_ANISOTROPY=1;var $u=class $u{constructor(e=0,t=0,n=0,s=1){this.x=e,this.y=t,this.z=n,this.w=s}get width(){return this.z}set width(e){this.z=e}get height(){return this.w}set height(e){this.w=e}set(e,t,n,s){return this.x=e,this.y=t,this.z=n,this.w=s,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this.w=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setW(e){return this.w=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;case 3:this.w=t;break;default:throw new Error("THREE.Vector4: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("THREE.Vector4: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this.w=e.w!==void 0?e.w:1,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this.w+=e.w,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this.w+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this.w=e.w+t.w,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this.w+=e.w*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this.w-=e.w,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this.w-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this.w=e.w-t.w,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this.w*=e.w,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this.w*=e,this}applyMatrix4(e){let t=this.x,n=this.y,s=this.z,r=this.w,o=e.elements;return this.x=o[0]*t+o[4]*n+o[8]*s+o[12]*r,this.y=o[1]*t+o[5]*n+o[9]*s+o[13]*r,this.z=o[2]*t+o[6]*n+o[10]*s+o[14]*r,this.w=o[3]*t+o[7]*n+o[11]*s+o[15]*r,this}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this.w/=e.w,this}divideScalar(e){return this.multiplyScalar(1/e)}setAxisAngleFromQuaternion(e){this.w=2*Math.acos(e.w);let t=Math.sqrt(1-e.w*e.w);return t<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=e.x/t,this.y=e.y/t,this.z=e.z/t),this}setAxisAngleFromRotationMatrix(e){let t,n,s,r,c=e.elements,l=c[0],d=c[4],u=c[8],h=c[1],m=c[5],g=c[9],v=c[2],p=c[6],f=c[10];if(Math.abs(d-h)<.01&&Math.abs(u-v)<.01&&Math.abs(g-p)<.01){if(Math.abs(d+h)<.1&&Math.abs(u+v)<.1&&Math.abs(g+p)<.1&&Math.abs(l+m+f-3)<.1)return this.set(1,0,0,0),this;t=Math.PI;let C=(l+1)/2,M=(m+1)/2,R=(f+1)/2,b=(d+h)/4,_=(u+v)/4,A=(g+p)/4;return C>M&&C>R?C<.01?(n=0,s=.707106781,r=.707106781):(n=Math.sqrt(C),s=b/n,r=_/n):M>R?M<.01?(n=.707106781,s=0,r=.707106781):(s=Math.sqrt(M),n=b/s,r=A/s):R<.01?(n=.707106781,s=.707106781,r=0):(r=Math.sqrt(R),n=_/r,s=A/r),this.set(n,s,r,t),this}let y=Math.sqrt((p-g)*(p-g)+(u-v)*(u-v)+(h-d)*(h-d));return Math.abs(y)<.001&&(y=1),this.x=(p-g)/y,this.y=(u-v)/y,this.z=(h-d)/y,this.w=Math.acos((l+m+f-1)/2),this}setFromMatrixPosition(e){let t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this.w=t[15],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this.w=Math.min(this.w,e.w),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this.w=Math.max(this.w,e.w),this}clamp(e,t){return this.x=lt(this.x,e.x,t.x),this.y=lt(this.y,e.y,t.y),this.z=lt(this.z,e.z,t.z),this.w=lt(this.w,e.w,t.w),this}clampScalar(e,t){return this.x=lt(this.x,e,t),this.y=lt(this.y,e,t),this.z=lt(this.z,e,t),this.w=lt(this.w,e,t),this}clampLength(e,t){let n=this.length();return this.divideScalar(n||1).multiplyScalar(lt(n,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z+this.w*e.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this.w+=(e.w-this.w)*t,this}lerpVectors(e,t,n){return this.x=e.x+(t.x-e.x)*n,this.y=e.y+(t.y-e.y)*n,this.z=e.z+(t.z-e.z)*n,this.w=e.w+(t.w-e.w)*n,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z&&e.w===this.w}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this.w=e[t+3],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e[t+3]=this.w,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this.w=e.getW(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}};$u.prototype.isVector4=!0;var Ct=$u,Cl=class extends Ci{constructor(e=1,t=1,n={}){super(),n=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:Xn,depthBuffer:!0,stencilBuffer:!1,resolveColorBuffer:!0,resolveDepthBuffer:!0,resolveStencilBuffer:!0,storeMultisampledColorBuffer:!0,storeMultisampledDepthBuffer:!0,storeMultisampledStencilBuffer:!0,depthTexture:null,samples:0,count:1,depth:1,multiview:!1,useArrayDepthTexture:!1},n),this.isRenderTarget=!0,this.width=e,this.height=t,this.depth=n.depth,this.scissor=new Ct(0,0,e,t),this.scissorTest=!1,this.viewport=new Ct(0,0,e,t),this.textures=[];let s=n.count;for(let r=0;r<s;r++)this.textures[r]=new jn({width:e,height:t,depth:n.depth}),this.textures[r].isRenderTargetTexture=!0,this.textures[r].renderTarget=this;this._setTextureOptions(n),this.depthBuffer=n.depthBuffer,this.stencilBuffer=n.stencilBuffer,this.resolveColorBuffer=n.resolveColorBuffer,this.resolveDepthBuffer=n.resolveDepthBuffer,this.resolveStencilBuffer=n.resolveStencilBuffer,this.storeMultisampledColorBuffer=n.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=n.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=n.storeMultisampledStencilBuffer,this._depthTexture=null,this.depthTexture=n.depthTexture,this.samples=n.samples,this.multiview=n.multiview,this.useArrayDepthTexture=n.useArrayDepthTexture}_setTextureOptions(e={}){let t={minFilter:Xn,generateMipmaps:!1,flipY:!1,internalFormat:null};e.mapping!==void 0&&(t.mapping=e.mapping),e.wrapS!==void 0&&(t.wrapS=e.wrapS),e.wrapT!==void 0&&(t.wrapT=e.wrapT),e.wrapR!==void 0&&(t.wrapR=e.wrapR),e.magFilter!==void 0&&(t.magFilter=e.magFilter),e.minFilter!==void 0&&(t.minFilter=e.minFilter),e.format!==void 0&&(t.format=e.format),e.type!==void 0&&(t.type=e.type),e.anisotropy!==void 0&&(t.anisotropy=e.anisotropy),e.colorSpace!==void 0&&(t.colorSpace=e.colorSpace),e.flipY!==void 0&&(t.flipY=e.flipY),e.generateMipmaps!==void 0&&(t.generateMipmaps=e.generateMipmaps),e.mipmapsAutoUpdate!==void 0&&(t.mipmapsAutoUpdate=e.mipmapsAutoUpdate),e.internalFormat!==void 0&&(t.internalFormat=e.internalFormat);for(let n=0;n<this.textures.length;n++)this.textures[n].setValues(t)}get texture(){return this.textures[0]}set texture(e){this.textures[0]=e}set depthTexture(e){this._depthTexture!==null&&this._depthTexture.renderTarget===this&&(this._depthTexture.renderTarget=null),e!==null&&e.renderTarget===null&&(e.renderTarget=this),this._depthTexture=e}get depthTexture(){return this._depthTexture}setSize(e,t,n=1){if(this.width!==e||this.height!==t||this.depth!==n){this.width=e,this.height=t,this.depth=n;for(let s=0,r=this.textures.length;s<r;s++)this.textures[s].image.width=e,this.textures[s].image.height=t,this.textures[s].image.depth=n,this.textures[s].isData3DTexture!==!0&&(this.textures[s].isArrayTexture=this.textures[s].image.depth>1);this.dispose()}this.viewport.set(0,0,e,t),this.scissor.set(0,0,e,t)}clone(){return new this.constructor().copy(this)}copy(e){this.width=e.width,this.height=e.height,this.depth=e.depth,this.scissor.copy(e.scissor),this.scissorTest=e.scissorTest,this.viewport.copy(e.viewport),this.textures.length=0;for(let t=0,n=e.textures.length;t<n;t++){this.textures[t]=e.textures[t].clone(),this.textures[t].isRenderTargetTexture=!0,this.textures[t].renderTarget=this;let s=Object.assign({},e.textures[t].image);this.textures[t].source=new Jr(s)}if(this.depthBuffer=e.depthBuffer,this.stencilBuffer=e.stencilBuffer,this.resolveColorBuffer=e.resolveColorBuffer,this.resolveDepthBuffer=e.resolveDepthBuffer,this.resolveStencilBuffer=e.resolveStencilBuffer,this.storeMultisampledColorBuffer=e.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=e.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=e.storeMultisampledStencilBuffer,e.depthTexture!==null)if(e.depthTexture.renderTarget===e){let t=e.depthTexture.clone();t.renderTarget=null,this.depthTexture=t}else this.depthTexture=e.depthTexture;else this.depthTexture=null;return this.samples=e.samples,this.multiview=e.multiview,this.useArrayDepthTexture=e.useArrayDepthTexture,this}dispose(){this.dispatchEvent({type:"dispose"})}},hi=class extends Cl{constructor(e=1,t=1,n={}){super(e,t,n),this.isWebGLRenderTarget=!0}},Zo=class extends jn{constructor(e=null,t=1,n=1,s=1){super(null),this.isDataArrayTexture=!0,this.image={data:e,width:t,height:n,depth:s},this.magFilter=Tn,this.minFilter=Tn,this.wrapR=qi,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}addLayerUpdate(e){this.layerUpdates.add(e)}clearLayerUpdates(){this.layerUpdates.clear()}};var Pl=class extends jn{constructor(e=null,t=1,n=1,s=1){super(null),this.isData3DTexture=!0,this.image={data:e,width:t,height:n,depth:s},this.magFilter=Tn,this.minFilter=Tn,this.wrapR=qi,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}};var Kl=class Kl{constructor(e,t,n,s,r,o,a,c,l,d,u,h,m,g,v,p){this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],e!==void 0&&this.set(e,t,n,s,r,o,a,c,l,d,u,h,m,g,v,p)}set(e,t,n,s,r,o,a,c,l,d,u,h,m,g,v,p){let f=this.elements;return f[0]=e,f[4]=t,f[8]=n,f[12]=s,f[1]=r,f[5]=o,f[9]=a,f[13]=c,f[2]=l,f[6]=d,f[10]=u,f[14]=h,f[3]=m,f[7]=g,f[11]=v,f[15]=p,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new Kl().fromArray(this.elements)}copy(e){let t=this.elements,n=e.elements;return t[0]=n[0],t[1]=n[1],t[2]=n[2],t[3]=n[3],t[4]=n[4],t[5]=n[5],t[6]=n[6],t[7]=n[7],t[8]=n[8],t[9]=n[9],t[10]=n[10],t[11]=n[11],t[12]=n[12],t[13]=n[13],t[14]=n[14],t[15]=n[15],this}copyPosition(e){let t=this.elements,n=e.elements;return t[12]=n[12],t[13]=n[13],t[14]=n[14],this}setFromMatrix3(e){let t=e.elements;return this.set(t[0],t[3],t[6],0,t[1],t[4],t[7],0,t[2],t[5],t[8],0,0,0,0,1),this}extractBasis(e,t,n){return this.determinantAffine()===0?(e.set(1,0,0),t.set(0,1,0),n.set(0,0,1),this):(e.setFromMatrixColumn(this,0),t.setFromMatrixColumn(this,1),n.setFromMatrixColumn(this,2),this)}makeBasis(e,t,n){return this.set(e.x,t.x,n.x,0,e.y,t.y,n.y,0,e.z,t.z,n.z,0,0,0,0,1),this}extractRotation(e){if(e.determinantAffine()===0)return this.identity();let t=this.elements,n=e.elements,s=1/Ir.setFromMatrixColumn(e,0).length(),r=1/Ir.setFromMatrixColumn(e,1).length(),o=1/Ir.setFromMatrixColumn(e,2).length();return t[0]=n[0]*s,t[1]=n[1]*s,t[2]=n[2]*s,t[3]=0,t[4]=n[4]*r,t[5]=n[5]*r,t[6]=n[6]*r,t[7]=0,t[8]=n[8]*o,t[9]=n[9]*o,t[10]=n[10]*o,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromEuler(e){let t=this.elements,n=e.x,s=e.y,r=e.z,o=Math.cos(n),a=Math.sin(n),c=Math.cos(s),l=Math.sin(s),d=Math.cos(r),u=Math.sin(r);if(e.order==="XYZ"){let h=o*d,m=o*u,g=a*d,v=a*u;t[0]=c*d,t[4]=-c*u,t[8]=l,t[1]=m+g*l,t[5]=h-v*l,t[9]=-a*c,t[2]=v-h*l,t[6]=g+m*l,t[10]=o*c}else if(e.order==="YXZ"){let h=c*d,m=c*u,g=l*d,v=l*u;t[0]=h+v*a,t[4]=g*a-m,t[8]=o*l,t[1]=o*u,t[5]=o*d,t[9]=-a,t[2]=m*a-g,t[6]=v+h*a,t[10]=o*c}else if(e.order==="ZXY"){let h=c*d,m=c*u,g=l*d,v=l*u;t[0]=h-v*a,t[4]=-o*u,t[8]=g+m*a,t[1]=m+g*a,t[5]=o*d,t[9]=v-h*a,t[2]=-o*l,t[6]=a,t[10]=o*c}else if(e.order==="ZYX"){let h=o*d,m=o*u,g=a*d,v=a*u;t[0]=c*d,t[4]=g*l-m,t[8]=h*l+v,t[1]=c*u,t[5]=v*l+h,t[9]=m*l-g,t[2]=-l,t[6]=a*c,t[10]=o*c}else if(e.order==="YZX"){let h=o*c,m=o*l,g=a*c,v=a*l;t[0]=c*d,t[4]=v-h*u,t[8]=g*u+m,t[1]=u,t[5]=o*d,t[9]=-a*d,t[2]=-l*d,t[6]=m*u+g,t[10]=h-v*u}else if(e.order==="XZY"){let h=o*c,m=o*l,g=a*c,v=a*l;t[0]=c*d,t[4]=-u,t[8]=l*d,t[1]=h*u+v,t[5]=o*d,t[9]=m*u-g,t[2]=g*u-m,t[6]=a*d,t[10]=v*u+h}return t[3]=0,t[7]=0,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromQuaternion(e){return this.compose(r_,e,o_)}lookAt(e,t,n){let s=this.elements;return oi.subVectors(e,t),oi.lengthSq()===0&&(oi.z=1),oi.normalize(),Is.crossVectors(n,oi),Is.lengthSq()===0&&(Math.abs(n.z)===1?oi.x+=1e-4:oi.z+=1e-4,oi.normalize(),Is.crossVectors(n,oi)),Is.normalize(),qa.crossVectors(oi,Is),s[0]=Is.x,s[4]=qa.x,s[8]=oi.x,s[1]=Is.y,s[5]=qa.y,s[9]=oi.y,s[2]=Is.z,s[6]=qa.z,s[10]=oi.z,this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){let n=e.elements,s=t.elements,r=this.elements,o=n[0],a=n[4],c=n[8],l=n[12],d=n[1],u=n[5],h=n[9],m=n[13],g=n[2],v=n[6],p=n[10],f=n[14],y=n[3],C=n[7],M=n[11],R=n[15],b=s[0],_=s[4],A=s[8],H=s[12],O=s[1],T=s[5],F=s[9],B=s[13],D=s[2],V=s[6],Y=s[10],$=s[14],ce=s[3],P=s[7],I=s[11],q=s[15];return r[0]=o*b+a*O+c*D+l*ce,r[4]=o*_+a*T+c*V+l*P,r[8]=o*A+a*F+c*Y+l*I,r[12]=o*H+a*B+c*$+l*q,r[1]=d*b+u*O+h*D+m*ce,r[5]=d*_+u*T+h*V+m*P,r[9]=d*A+u*F+h*Y+m*I,r[13]=d*H+u*B+h*$+m*q,r[2]=g*b+v*O+p*D+f*ce,r[6]=g*_+v*T+p*V+f*P,r[10]=g*A+v*F+p*Y+f*I,r[14]=g*H+v*B+p*$+f*q,r[3]=y*b+C*O+M*D+R*ce,r[7]=y*_+C*T+M*V+R*P,r[11]=y*A+C*F+M*Y+R*I,r[15]=y*H+C*B+M*$+R*q,this}multiplyScalar(e){let t=this.elements;return t[0]*=e,t[4]*=e,t[8]*=e,t[12]*=e,t[1]*=e,t[5]*=e,t[9]*=e,t[13]*=e,t[2]*=e,t[6]*=e,t[10]*=e,t[14]*=e,t[3]*=e,t[7]*=e,t[11]*=e,t[15]*=e,this}determinant(){let e=this.elements,t=e[0],n=e[4],s=e[8],r=e[12],o=e[1],a=e[5],c=e[9],l=e[13],d=e[2],u=e[6],h=e[10],m=e[14],g=e[3],v=e[7],p=e[11],f=e[15],y=c*m-l*h,C=a*m-l*u,M=a*h-c*u,R=o*m-l*d,b=o*h-c*d,_=o*u-a*d;return t*(v*y-p*C+f*M)-n*(g*y-p*R+f*b)+s*(g*C-v*R+f*_)-r*(g*M-v*b+p*_)}determinantAffine(){let e=this.elements,t=e[0],n=e[4],s=e[8],r=e[1],o=e[5],a=e[9],c=e[2],l=e[6],d=e[10];return t*(o*d-a*l)-n*(r*d-a*c)+s*(r*l-o*c)}transpose(){let e=this.elements,t;return t=e[1],e[1]=e[4],e[4]=t,t=e[2],e[2]=e[8],e[8]=t,t=e[6],e[6]=e[9],e[9]=t,t=e[3],e[3]=e[12],e[12]=t,t=e[7],e[7]=e[13],e[13]=t,t=e[11],e[11]=e[14],e[14]=t,this}setPosition(e,t,n){let s=this.elements;return e.isVector3?(s[12]=e.x,s[13]=e.y,s[14]=e.z):(s[12]=e,s[13]=t,s[14]=n),this}invert(){let e=this.elements,t=e[0],n=e[1],s=e[2],r=e[3],o=e[4],a=e[5],c=e[6],l=e[7],d=e[8],u=e[9],h=e[10],m=e[11],g=e[12],v=e[13],p=e[14],f=e[15],y=t*a-n*o,C=t*c-s*o,M=t*l-r*o,R=n*c-s*a,b=n*l-r*a,_=s*l-r*c,A=d*v-u*g,H=d*p-h*g,O=d*f-m*g,T=u*p-h*v,F=u*f-m*v,B=h*f-m*p,D=y*B-C*F+M*T+R*O-b*H+_*A;if(D===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);let V=1/D;return e[0]=(a*B-c*F+l*T)*V,e[1]=(s*F-n*B-r*T)*V,e[2]=(v*_-p*b+f*R)*V,e[3]=(h*b-u*_-m*R)*V,e[4]=(c*O-o*B-l*H)*V,e[5]=(t*B-s*O+r*H)*V,e[6]=(p*M-g*_-f*C)*V,e[7]=(d*_-h*M+m*C)*V,e[8]=(o*F-a*O+l*A)*V,e[9]=(n*O-t*F-r*A)*V,e[10]=(g*b-v*M+f*y)*V,e[11]=(u*M-d*b-m*y)*V,e[12]=(a*H-o*T-c*A)*V,e[13]=(t*T-n*H+s*A)*V,e[14]=(v*C-g*R-p*y)*V,e[15]=(d*R-u*C+h*y)*V,this}scale(e){let t=this.elements,n=e.x,s=e.y,r=e.z;return t[0]*=n,t[4]*=s,t[8]*=r,t[1]*=n,t[5]*=s,t[9]*=r,t[2]*=n,t[6]*=s,t[10]*=r,t[3]*=n,t[7]*=s,t[11]*=r,this}getMaxScaleOnAxis(){let e=this.elements,t=e[0]*e[0]+e[1]*e[1]+e[2]*e[2],n=e[4]*e[4]+e[5]*e[5]+e[6]*e[6],s=e[8]*e[8]+e[9]*e[9]+e[10]*e[10];return Math.sqrt(Math.max(t,n,s))}makeTranslation(e,t,n){return e.isVector3?this.set(1,0,0,e.x,0,1,0,e.y,0,0,1,e.z,0,0,0,1):this.set(1,0,0,e,0,1,0,t,0,0,1,n,0,0,0,1),this}makeRotationX(e){let t=Math.cos(e),n=Math.sin(e);return this.set(1,0,0,0,0,t,-n,0,0,n,t,0,0,0,0,1),this}makeRotationY(e){let t=Math.cos(e),n=Math.sin(e);return this.set(t,0,n,0,0,1,0,0,-n,0,t,0,0,0,0,1),this}makeRotationZ(e){let t=Math.cos(e),n=Math.sin(e);return this.set(t,-n,0,0,n,t,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(e,t){let n=Math.cos(t),s=Math.sin(t),r=1-n,o=e.x,a=e.y,c=e.z,l=r*o,d=r*a;return this.set(l*o+n,l*a-s*c,l*c+s*a,0,l*a+s*c,d*a+n,d*c-s*o,0,l*c-s*a,d*c+s*o,r*c*c+n,0,0,0,0,1),this}makeScale(e,t,n){return this.set(e,0,0,0,0,t,0,0,0,0,n,0,0,0,0,1),this}makeShear(e,t,n,s,r,o){return this.set(1,n,r,0,e,1,o,0,t,s,1,0,0,0,0,1),this}compose(e,t,n){let s=this.elements,r=t._x,o=t._y,a=t._z,c=t._w,l=r+r,d=o+o,u=a+a,h=r*l,m=r*d,g=r*u,v=o*d,p=o*u,f=a*u,y=c*l,C=c*d,M=c*u,R=n.x,b=n.y,_=n.z;return s[0]=(1-(v+f))*R,s[1]=(m+M)*R,s[2]=(g-C)*R,s[3]=0,s[4]=(m-M)*b,s[5]=(1-(h+f))*b,s[6]=(p+y)*b,s[7]=0,s[8]=(g+C)*_,s[9]=(p-y)*_,s[10]=(1-(h+v))*_,s[11]=0,s[12]=e.x,s[13]=e.y,s[14]=e.z,s[15]=1,this}decompose(e,t,n){let s=this.elements;e.x=s[12],e.y=s[13],e.z=s[14];let r=this.determinantAffine();if(r===0)return n.set(1,1,1),t.identity(),this;let o=Ir.set(s[0],s[1],s[2]).length(),a=Ir.set(s[4],s[5],s[6]).length(),c=Ir.set(s[8],s[9],s[10]).length();r<0&&(o=-o),Ti.copy(this);let l=1/o,d=1/a,u=1/c;return Ti.elements[0]*=l,Ti.elements[1]*=l,Ti.elements[2]*=l,Ti.elements[4]*=d,Ti.elements[5]*=d,Ti.elements[6]*=d,Ti.elements[8]*=u,Ti.elements[9]*=u,Ti.elements[10]*=u,t.setFromRotationMatrix(Ti),n.x=o,n.y=a,n.z=c,this}makePerspective(e,t,n,s,r,o,a=vi,c=!1){let l=this.elements,d=2*r/(t-e),u=2*r/(n-s),h=(t+e)/(t-e),m=(n+s)/(n-s),g,v;if(c)g=r/(o-r),v=o*r/(o-r);else if(a===vi)g=-(o+r)/(o-r),v=-2*o*r/(o-r);else if(a===qr)g=-o/(o-r),v=-o*r/(o-r);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+a);return l[0]=d,l[4]=0,l[8]=h,l[12]=0,l[1]=0,l[5]=u,l[9]=m,l[13]=0,l[2]=0,l[6]=0,l[10]=g,l[14]=v,l[3]=0,l[7]=0,l[11]=-1,l[15]=0,this}makeOrthographic(e,t,n,s,r,o,a=vi,c=!1){let l=this.elements,d=2/(t-e),u=2/(n-s),h=-(t+e)/(t-e),m=-(n+s)/(n-s),g,v;if(c)g=1/(o-r),v=o/(o-r);else if(a===vi)g=-2/(o-r),v=-(o+r)/(o-r);else if(a===qr)g=-1/(o-r),v=-r/(o-r);else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+a);return l[0]=d,l[4]=0,l[8]=0,l[12]=h,l[1]=0,l[5]=u,l[9]=0,l[13]=m,l[2]=0,l[6]=0,l[10]=g,l[14]=v,l[3]=0,l[7]=0,l[11]=0,l[15]=1,this}equals(e){let t=this.elements,n=e.elements;for(let s=0;s<16;s++)if(t[s]!==n[s])return!1;return!0}fromArray(e,t=0){for(let n=0;n<16;n++)this.elements[n]=e[n+t];return this}toArray(e=[],t=0){let n=this.elements;return e[t]=n[0],e[t+1]=n[1],e[t+2]=n[2],e[t+3]=n[3],e[t+4]=n[4],e[t+5]=n[5],e[t+6]=n[6],e[t+7]=n[7],e[t+8]=n[8],e[t+9]=n[9],e[t+10]=n[10],e[t+11]=n[11],e[t+12]=n[12],e[t+13]=n[13],e[t+14]=n[14],e[t+15]=n[15],e}};Kl.prototype.isMatrix4=!0;var kt=Kl,Ir=new W,Ti=new kt,r_=new W(0,0,0),o_=new W(1,1,1),Is=new W,qa=new W,oi=new W,wf=new kt,Ef=new ci,gs=class i{constructor(e=0,t=0,n=0,s=i.DEFAULT_ORDER){this.isEuler=!0,this._x=e,this._y=t,this._z=n,this._order=s}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get order(){return this._order}set order(e){this._order=e,this._onChangeCallback()}set(e,t,n,s=this._order){return this._x=e,this._y=t,this._z=n,this._order=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(e){return this._x=e._x,this._y=e._y,this._z=e._z,this._order=e._order,this._onChangeCallback(),this}setFromRotationMatrix(e,t=this._order,n=!0){let s=e.elements,r=s[0],o=s[4],a=s[8],c=s[1],l=s[5],d=s[9],u=s[2],h=s[6],m=s[10];switch(t){case"XYZ":this._y=Math.asin(lt(a,-1,1)),Math.abs(a)<.9999999?(this._x=Math.atan2(-d,m),this._z=Math.atan2(-o,r)):(this._x=Math.atan2(h,l),this._z=0);break;case"YXZ":this._x=Math.asin(-lt(d,-1,1)),Math.abs(d)<.9999999?(this._y=Math.atan2(a,m),this._z=Math.atan2(c,l)):(this._y=Math.atan2(-u,r),this._z=0);break;case"ZXY":this._x=Math.asin(lt(h,-1,1)),Math.abs(h)<.9999999?(this._y=Math.atan2(-u,m),this._z=Math.atan2(-o,l)):(this._y=0,this._z=Math.atan2(c,r));break;case"ZYX":this._y=Math.asin(-lt(u,-1,1)),Math.abs(u)<.9999999?(this._x=Math.atan2(h,m),this._z=Math.atan2(c,r)):(this._x=0,this._z=Math.atan2(-o,l));break;case"YZX":this._z=Math.asin(lt(c,-1,1)),Math.abs(c)<.9999999?(this._x=Math.atan2(-d,l),this._y=Math.atan2(-u,r)):(this._x=0,this._y=Math.atan2(a,m));break;case"XZY":this._z=Math.asin(-lt(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(h,l),this._y=Math.atan2(a,r)):(this._x=Math.atan2(-d,m),this._y=0);break;default:Ye("Euler: .setFromRotationMatrix() encountered an unknown order: "+t)}return this._order=t,n===!0&&this._onChangeCallback(),this}setFromQuaternion(e,t,n){return wf.makeRotationFromQuaternion(e),this.setFromRotationMatrix(wf,t,n)}setFromVector3(e,t=this._order){return this.set(e.x,e.y,e.z,t)}reorder(e){return Ef.setFromEuler(this),this.setFromQuaternion(Ef,e)}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._order===this._order}fromArray(e){return this._x=e[0],this._y=e[1],this._z=e[2],e[3]!==void 0&&(this._order=e[3]),this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._order,e}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}};gs.DEFAULT_ORDER="XYZ";var Jo=class{constructor(){this.mask=1}set(e){this.mask=(1<<e|0)>>>0}enable(e){this.mask|=1<<e|0}enableAll(){this.mask=-1}toggle(e){this.mask^=1<<e|0}disable(e){this.mask&=~(1<<e|0)}disableAll(){this.mask=0}test(e){return(this.mask&e.mask)!==0}isEnabled(e){return(this.mask&(1<<e|0))!==0}},a_=0,Tf=new W,Lr=new ci,cs=new kt,Ya=new W,Fo=new W,l_=new W,c_=new ci,Af=new W(1,0,0),Rf=new W(0,1,0),Cf=new W(0,0,1),Pf={type:"added"},h_={type:"removed"},Dr={type:"childadded",child:null},Fh={type:"childremoved",child:null},Cn=class i extends Ci{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:a_++}),this.uuid=Xs(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=i.DEFAULT_UP.clone();let e=new W,t=new gs,n=new ci,s=new W(1,1,1);function r(){n.setFromEuler(t,!1)}function o(){t.setFromQuaternion(n,void 0,!1)}t._onChange(r),n._onChange(o),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:e},rotation:{configurable:!0,enumerable:!0,value:t},quaternion:{configurable:!0,enumerable:!0,value:n},scale:{configurable:!0,enumerable:!0,value:s},modelViewMatrix:{value:new kt},normalMatrix:{value:new st}}),this.matrix=new kt,this.matrixWorld=new kt,this.matrixAutoUpdate=i.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=i.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new Jo,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.customDepthMaterial=void 0,this.customDistanceMaterial=void 0,this.static=!1,this.userData={},this.pivot=null}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(e){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(e),this.matrix.decompose(this.position,this.quaternion,this.scale),this.pivot!==null&&this.position.copy(this.pivot).applyMatrix4(this.matrix).sub(this.pivot)}applyQuaternion(e){return this.quaternion.premultiply(e),this}setRotationFromAxisAngle(e,t){this.quaternion.setFromAxisAngle(e,t)}setRotationFromEuler(e){this.quaternion.setFromEuler(e,!0)}setRotationFromMatrix(e){this.quaternion.setFromRotationMatrix(e)}setRotationFromQuaternion(e){this.quaternion.copy(e)}rotateOnAxis(e,t){return Lr.setFromAxisAngle(e,t),this.quaternion.multiply(Lr),this}rotateOnWorldAxis(e,t){return Lr.setFromAxisAngle(e,t),this.quaternion.premultiply(Lr),this}rotateX(e){return this.rotateOnAxis(Af,e)}rotateY(e){return this.rotateOnAxis(Rf,e)}rotateZ(e){return this.rotateOnAxis(Cf,e)}translateOnAxis(e,t){return Tf.copy(e).applyQuaternion(this.quaternion),this.position.add(Tf.multiplyScalar(t)),this}translateX(e){return this.translateOnAxis(Af,e)}translateY(e){return this.translateOnAxis(Rf,e)}translateZ(e){return this.translateOnAxis(Cf,e)}localToWorld(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(this.matrixWorld)}worldToLocal(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(cs.copy(this.matrixWorld).invert())}lookAt(e,t,n){e.isVector3?Ya.copy(e):Ya.set(e,t,n);let s=this.parent;this.updateWorldMatrix(!0,!1),Fo.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?cs.lookAt(Fo,Ya,this.up):cs.lookAt(Ya,Fo,this.up),this.quaternion.setFromRotationMatrix(cs),s&&(cs.extractRotation(s.matrixWorld),Lr.setFromRotationMatrix(cs),this.quaternion.premultiply(Lr.invert()))}add(e){if(arguments.length>1){for(let t=0;t<arguments.length;t++)this.add(arguments[t]);return this}return e===this?(it("Object3D.add: object can't be added as a child of itself.",e),this):(e&&e.isObject3D?(e.removeFromParent(),e.parent=this,this.children.push(e),e.dispatchEvent(Pf),Dr.child=e,this.dispatchEvent(Dr),Dr.child=null):it("Object3D.add: object not an instance of THREE.Object3D.",e),this)}remove(e){if(arguments.length>1){for(let n=0;n<arguments.length;n++)this.remove(arguments[n]);return this}let t=this.children.indexOf(e);return t!==-1&&(e.parent=null,this.children.splice(t,1),e.dispatchEvent(h_),Fh.child=e,this.dispatchEvent(Fh),Fh.child=null),this}removeFromParent(){let e=this.parent;return e!==null&&e.remove(this),this}clear(){return this.remove(...this.children)}attach(e){return this.updateWorldMatrix(!0,!1),cs.copy(this.matrixWorld).invert(),e.parent!==null&&(e.parent.updateWorldMatrix(!0,!1),cs.multiply(e.parent.matrixWorld)),e.applyMatrix4(cs),e.removeFromParent(),e.parent=this,this.children.push(e),e.updateWorldMatrix(!1,!0),e.dispatchEvent(Pf),Dr.child=e,this.dispatchEvent(Dr),Dr.child=null,this}getObjectById(e){return this.getObjectByProperty("id",e)}getObjectByName(e){return this.getObjectByProperty("name",e)}getObjectByProperty(e,t){if(this[e]===t)return this;for(let n=0,s=this.children.length;n<s;n++){let o=this.children[n].getObjectByProperty(e,t);if(o!==void 0)return o}}getObjectsByProperty(e,t,n=[]){this[e]===t&&n.push(this);let s=this.children;for(let r=0,o=s.length;r<o;r++)s[r].getObjectsByProperty(e,t,n);return n}getWorldPosition(e){return this.updateWorldMatrix(!0,!1),e.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(Fo,e,l_),e}getWorldScale(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(Fo,c_,e),e}getWorldDirection(e){this.updateWorldMatrix(!0,!1);let t=this.matrixWorld.elements;return e.set(t[8],t[9],t[10]).normalize()}raycast(){}intersectsFrustum(){return!0}traverse(e){e(this);let t=this.children;for(let n=0,s=t.length;n<s;n++)t[n].traverse(e)}traverseVisible(e){if(this.visible===!1)return;e(this);let t=this.children;for(let n=0,s=t.length;n<s;n++)t[n].traverseVisible(e)}traverseAncestors(e){let t=this.parent;t!==null&&(e(t),t.traverseAncestors(e))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale);let e=this.pivot;if(e!==null){let t=e.x,n=e.y,s=e.z,r=this.matrix.elements;r[12]+=t-r[0]*t-r[4]*n-r[8]*s,r[13]+=n-r[1]*t-r[5]*n-r[9]*s,r[14]+=s-r[2]*t-r[6]*n-r[10]*s}this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(e){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||e)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,e=!0);let t=this.children;for(let n=0,s=t.length;n<s;n++)t[n].updateMatrixWorld(e)}updateWorldMatrix(e,t,n=!1){let s=this.parent;if(e===!0&&s!==null&&s.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||n)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,n=!0),t===!0){let r=this.children;for(let o=0,a=r.length;o<a;o++)r[o].updateWorldMatrix(!1,!0,n)}}toJSON(e){let t=e===void 0||typeof e=="string",n={};t&&(e={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},n.metadata={version:4.7,type:"Object",generator:"Object3D.toJSON"});let s={};s.uuid=this.uuid,s.type=this.type,s.name=this.name,s.castShadow=this.castShadow,s.receiveShadow=this.receiveShadow,s.visible=this.visible,s.frustumCulled=this.frustumCulled,s.renderOrder=this.renderOrder,s.static=this.static,s.matrixAutoUpdate=this.matrixAutoUpdate,Object.keys(this.userData).length>0&&(s.userData=this.userData),s.layers=this.layers.mask,s.matrix=this.matrix.toArray(),s.up=this.up.toArray(),this.pivot!==null&&(s.pivot=this.pivot.toArray()),this.morphTargetDictionary!==void 0&&(s.morphTargetDictionary=Object.assign({},this.morphTargetDictionary)),this.morphTargetInfluences!==void 0&&(s.morphTargetInfluences=this.morphTargetInfluences.slice()),this.isInstancedMesh&&(s.type="InstancedMesh",s.count=this.count,s.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(s.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(s.type="BatchedMesh",s.perObjectFrustumCulled=this.perObjectFrustumCulled,s.sortObjects=this.sortObjects,s.drawRanges=this._drawRanges,s.reservedRanges=this._reservedRanges,s.geometryInfo=this._geometryInfo.map(a=>({...a,boundingBox:a.boundingBox?a.boundingBox.toJSON():void 0,boundingSphere:a.boundingSphere?a.boundingSphere.toJSON():void 0})),s.instanceInfo=this._instanceInfo.map(a=>({...a})),s.availableInstanceIds=this._availableInstanceIds.slice(),s.availableGeometryIds=this._availableGeometryIds.slice(),s.nextIndexStart=this._nextIndexStart,s.nextVertexStart=this._nextVertexStart,s.geometryCount=this._geometryCount,s.maxInstanceCount=this._maxInstanceCount,s.maxVertexCount=this._maxVertexCount,s.maxIndexCount=this._maxIndexCount,s.geometryInitialized=this._geometryInitialized,s.matricesTexture=this._matricesTexture.toJSON(e),s.indirectTexture=this._indirectTexture.toJSON(e),this._colorsTexture!==null&&(s.colorsTexture=this._colorsTexture.toJSON(e)),this.boundingSphere!==null&&(s.boundingSphere=this.boundingSphere.toJSON()),this.boundingBox!==null&&(s.boundingBox=this.boundingBox.toJSON()));function r(a,c){return a[c.uuid]===void 0&&(a[c.uuid]=c.toJSON(e)),c.uuid}if(this.isScene)this.background&&(this.background.isColor?s.background=this.background.toJSON():this.background.isTexture&&(s.background=this.background.toJSON(e).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(s.environment=this.environment.toJSON(e).uuid);else if(this.isMesh||this.isLine||this.isPoints){s.geometry=r(e.geometries,this.geometry);let a=this.geometry.parameters;if(a!==void 0&&a.shapes!==void 0){let c=a.shapes;if(Array.isArray(c))for(let l=0,d=c.length;l<d;l++){let u=c[l];r(e.shapes,u)}else r(e.shapes,c)}}if(this.isSkinnedMesh&&(s.bindMode=this.bindMode,s.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(r(e.skeletons,this.skeleton),s.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){let a=[];for(let c=0,l=this.material.length;c<l;c++)a.push(r(e.materials,this.material[c]));s.material=a}else s.material=r(e.materials,this.material);if(this.children.length>0){s.children=[];for(let a=0;a<this.children.length;a++)s.children.push(this.children[a].toJSON(e).object)}if(this.animations.length>0){s.animations=[];for(let a=0;a<this.animations.length;a++){let c=this.animations[a];s.animations.push(r(e.animations,c))}}if(t){let a=o(e.geometries),c=o(e.materials),l=o(e.textures),d=o(e.images),u=o(e.shapes),h=o(e.skeletons),m=o(e.animations),g=o(e.nodes);a.length>0&&(n.geometries=a),c.length>0&&(n.materials=c),l.length>0&&(n.textures=l),d.length>0&&(n.images=d),u.length>0&&(n.shapes=u),h.length>0&&(n.skeletons=h),m.length>0&&(n.animations=m),g.length>0&&(n.nodes=g)}return n.object=s,n;function o(a){let c=[];for(let l in a){let d=a[l];delete d.metadata,c.push(d)}return c}}clone(e){return new this.constructor().copy(this,e)}copy(e,t=!0){if(this.name=e.name,this.up.copy(e.up),this.position.copy(e.position),this.rotation.order=e.rotation.order,this.quaternion.copy(e.quaternion),this.scale.copy(e.scale),this.pivot=e.pivot!==null?e.pivot.clone():null,this.matrix.copy(e.matrix),this.matrixWorld.copy(e.matrixWorld),this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrixWorldAutoUpdate=e.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=e.matrixWorldNeedsUpdate,this.layers.mask=e.layers.mask,this.visible=e.visible,this.castShadow=e.castShadow,this.receiveShadow=e.receiveShadow,this.frustumCulled=e.frustumCulled,this.renderOrder=e.renderOrder,this.static=e.static,this.animations=e.animations.slice(),this.userData=JSON.parse(JSON.stringify(e.userData)),t===!0)for(let n=0;n<e.children.length;n++){let s=e.children[n];this.add(s.clone())}return this}dispose(){this.dispatchEvent({type:"dispose"})}};Cn.DEFAULT_UP=new W(0,1,0);Cn.DEFAULT_MATRIX_AUTO_UPDATE=!0;Cn.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;var Yi=class extends Cn{constructor(){super(),this.isGroup=!0,this.type="Group"}},u_={type:"move"},Kr=class{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new Yi,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new Yi,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new W,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new W),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new Yi,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new W,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new W,this._grip.eventsEnabled=!1),this._grip}dispatchEvent(e){return this._targetRay!==null&&this._targetRay.dispatchEvent(e),this._grip!==null&&this._grip.dispatchEvent(e),this._hand!==null&&this._hand.dispatchEvent(e),this}connect(e){if(e&&e.hand){let t=this._hand;if(t)for(let n of e.hand.values())this._getHandJoint(t,n)}return this.dispatchEvent({type:"connected",data:e}),this}disconnect(e){return this.dispatchEvent({type:"disconnected",data:e}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(e,t,n){let s=null,r=null,o=null,a=this._targetRay,c=this._grip,l=this._hand;if(e&&t.session.visibilityState!=="visible-blurred"){if(l&&e.hand){o=!0;for(let v of e.hand.values()){let p=t.getJointPose(v,n),f=this._getHandJoint(l,v);p!==null&&(f.matrix.fromArray(p.transform.matrix),f.matrix.decompose(f.position,f.quaternion,f.scale),f.matrixWorldNeedsUpdate=!0,f.jointRadius=p.radius),f.visible=p!==null}let d=l.joints["index-finger-tip"],u=l.joints["thumb-tip"],h=d.position.distanceTo(u.position),m=.02,g=.005;l.inputState.pinching&&h>m+g?(l.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:e.handedness,target:this})):!l.inputState.pinching&&h<=m-g&&(l.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:e.handedness,target:this}))}else c!==null&&e.gripSpace&&(r=t.getPose(e.gripSpace,n),r!==null&&(c.matrix.fromArray(r.transform.matrix),c.matrix.decompose(c.position,c.quaternion,c.scale),c.matrixWorldNeedsUpdate=!0,r.linearVelocity?(c.hasLinearVelocity=!0,c.linearVelocity.copy(r.linearVelocity)):c.hasLinearVelocity=!1,r.angularVelocity?(c.hasAngularVelocity=!0,c.angularVelocity.copy(r.angularVelocity)):c.hasAngularVelocity=!1,c.eventsEnabled&&c.dispatchEvent({type:"gripUpdated",data:e,target:this})));a!==null&&(s=t.getPose(e.targetRaySpace,n),s===null&&r!==null&&(s=r),s!==null&&(a.matrix.fromArray(s.transform.matrix),a.matrix.decompose(a.position,a.quaternion,a.scale),a.matrixWorldNeedsUpdate=!0,s.linearVelocity?(a.hasLinearVelocity=!0,a.linearVelocity.copy(s.linearVelocity)):a.hasLinearVelocity=!1,s.angularVelocity?(a.hasAngularVelocity=!0,a.angularVelocity.copy(s.angularVelocity)):a.hasAngularVelocity=!1,this.dispatchEvent(u_)))}return a!==null&&(a.visible=s!==null),c!==null&&(c.visible=r!==null),l!==null&&(l.visible=o!==null),this}_getHandJoint(e,t){if(e.joints[t.jointName]===void 0){let n=new Yi;n.matrixAutoUpdate=!1,n.visible=!1,e.joints[t.jointName]=n,e.add(n)}return e.joints[t.jointName]}},Lp={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},Ls={h:0,s:0,l:0},Za={h:0,s:0,l:0};function Oh(i,e,t){return t<0&&(t+=1),t>1&&(t-=1),t<1/6?i+(e-i)*6*t:t<1/2?e:t<2/3?i+(e-i)*6*(2/3-t):i}var ct=class{constructor(e,t,n){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(e,t,n)}set(e,t,n){if(t===void 0&&n===void 0){let s=e;s&&s.isColor?this.copy(s):typeof s=="number"?this.setHex(s):typeof s=="string"&&this.setStyle(s)}else this.setRGB(e,t,n);return this}setScalar(e){return this.r=e,this.g=e,this.b=e,this}setHex(e,t=On){return e=Math.floor(e),this.r=(e>>16&255)/255,this.g=(e>>8&255)/255,this.b=(e&255)/255,_t.colorSpaceToWorking(this,t),this}setRGB(e,t,n,s=_t.workingColorSpace){return this.r=e,this.g=t,this.b=n,_t.colorSpaceToWorking(this,s),this}setHSL(e,t,n,s=_t.workingColorSpace){if(e=Nu(e,1),t=lt(t,0,1),n=lt(n,0,1),t===0)this.r=this.g=this.b=n;else{let r=n<=.5?n*(1+t):n+t-n*t,o=2*n-r;this.r=Oh(o,r,e+1/3),this.g=Oh(o,r,e),this.b=Oh(o,r,e-1/3)}return _t.colorSpaceToWorking(this,s),this}setStyle(e,t=On){function n(r){r!==void 0&&parseFloat(r)<1&&Ye("Color: Alpha component of "+e+" will be ignored.")}let s;if(s=/^(\w+)\(([^\)]*)\)/.exec(e)){let r,o=s[1],a=s[2];switch(o){case"rgb":case"rgba":if(r=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return n(r[4]),this.setRGB(Math.min(255,parseInt(r[1],10))/255,Math.min(255,parseInt(r[2],10))/255,Math.min(255,parseInt(r[3],10))/255,t);if(r=/^\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return n(r[4]),this.setRGB(Math.min(100,parseFloat(r[1]))/100,Math.min(100,parseFloat(r[2]))/100,Math.min(100,parseFloat(r[3]))/100,t);break;case"hsl":case"hsla":if(r=/^\s*([+-]?(?:\d+(?:\.\d+)?|\.\d+))\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return n(r[4]),this.setHSL(parseFloat(r[1])/360,parseFloat(r[2])/100,parseFloat(r[3])/100,t);break;default:Ye("Color: Unknown color model "+e)}}else if(s=/^\#([A-Fa-f\d]+)$/.exec(e)){let r=s[1],o=r.length;if(o===3)return this.setRGB(parseInt(r.charAt(0),16)/15,parseInt(r.charAt(1),16)/15,parseInt(r.charAt(2),16)/15,t);if(o===6)return this.setHex(parseInt(r,16),t);Ye("Color: Invalid hex color "+e)}else if(e&&e.length>0)return this.setColorName(e,t);return this}setColorName(e,t=On){let n=Lp[e.toLowerCase()];return n!==void 0?this.setHex(n,t):Ye("Color: Unknown color "+e),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(e){return this.r=e.r,this.g=e.g,this.b=e.b,this}copySRGBToLinear(e){return this.r=ps(e.r),this.g=ps(e.g),this.b=ps(e.b),this}copyLinearToSRGB(e){return this.r=$r(e.r),this.g=$r(e.g),this.b=$r(e.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(e=On){return _t.workingToColorSpace(Fn.copy(this),e),Math.round(lt(Fn.r*255,0,255))*65536+Math.round(lt(Fn.g*255,0,255))*256+Math.round(lt(Fn.b*255,0,255))}getHexString(e=On){return("000000"+this.getHex(e).toString(16)).slice(-6)}getHSL(e,t=_t.workingColorSpace){_t.workingToColorSpace(Fn.copy(this),t);let n=Fn.r,s=Fn.g,r=Fn.b,o=Math.max(n,s,r),a=Math.min(n,s,r),c,l,d=(a+o)/2;if(a===o)c=0,l=0;else{let u=o-a;switch(l=d<=.5?u/(o+a):u/(2-o-a),o){case n:c=(s-r)/u+(s<r?6:0);break;case s:c=(r-n)/u+2;break;case r:c=(n-s)/u+4;break}c/=6}return e.h=c,e.s=l,e.l=d,e}getRGB(e,t=_t.workingColorSpace){return _t.workingToColorSpace(Fn.copy(this),t),e.r=Fn.r,e.g=Fn.g,e.b=Fn.b,e}getStyle(e=On){_t.workingToColorSpace(Fn.copy(this),e);let t=Fn.r,n=Fn.g,s=Fn.b;return e!==On?`color(${e} ${t.toFixed(3)} ${n.toFixed(3)} ${s.toFixed(3)})`:`rgb(${Math.round(t*255)},${Math.round(n*255)},${Math.round(s*255)})`}offsetHSL(e,t,n){return this.getHSL(Ls),this.setHSL(Ls.h+e,Ls.s+t,Ls.l+n)}add(e){return this.r+=e.r,this.g+=e.g,this.b+=e.b,this}addColors(e,t){return this.r=e.r+t.r,this.g=e.g+t.g,this.b=e.b+t.b,this}addScalar(e){return this.r+=e,this.g+=e,this.b+=e,this}sub(e){return this.r=Math.max(0,this.r-e.r),this.g=Math.max(0,this.g-e.g),this.b=Math.max(0,this.b-e.b),this}multiply(e){return this.r*=e.r,this.g*=e.g,this.b*=e.b,this}multiplyScalar(e){return this.r*=e,this.g*=e,this.b*=e,this}lerp(e,t){return this.r+=(e.r-this.r)*t,this.g+=(e.g-this.g)*t,this.b+=(e.b-this.b)*t,this}lerpColors(e,t,n){return this.r=e.r+(t.r-e.r)*n,this.g=e.g+(t.g-e.g)*n,this.b=e.b+(t.b-e.b)*n,this}lerpHSL(e,t){this.getHSL(Ls),e.getHSL(Za);let n=Go(Ls.h,Za.h,t),s=Go(Ls.s,Za.s,t),r=Go(Ls.l,Za.l,t);return this.setHSL(n,s,r),this}setFromVector3(e){return this.r=e.x,this.g=e.y,this.b=e.z,this}applyMatrix3(e){let t=this.r,n=this.g,s=this.b,r=e.elements;return this.r=r[0]*t+r[3]*n+r[6]*s,this.g=r[1]*t+r[4]*n+r[7]*s,this.b=r[2]*t+r[5]*n+r[8]*s,this}equals(e){return e.r===this.r&&e.g===this.g&&e.b===this.b}fromArray(e,t=0){return this.r=e[t],this.g=e[t+1],this.b=e[t+2],this}toArray(e=[],t=0){return e[t]=this.r,e[t+1]=this.g,e[t+2]=this.b,e}fromBufferAttribute(e,t){return this.r=e.getX(t),this.g=e.getY(t),this.b=e.getZ(t),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}},Fn=new ct;ct.NAMES=Lp;var Ko=class extends Cn{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new gs,this.environmentIntensity=1,this.environmentRotation=new gs,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(e,t){return super.copy(e,t),this.background=e.background!==null?e.background.clone():null,this.environment=e.environment!==null?e.environment.clone():null,this.fog=e.fog!==null?e.fog.clone():null,this.backgroundBlurriness=e.backgroundBlurriness,this.backgroundIntensity=e.backgroundIntensity,this.backgroundRotation.copy(e.backgroundRotation),this.environmentIntensity=e.environmentIntensity,this.environmentRotation.copy(e.environmentRotation),this.overrideMaterial=e.overrideMaterial!==null?e.overrideMaterial.clone():null,this.matrixAutoUpdate=e.matrixAutoUpdate,this}toJSON(e){let t=super.toJSON(e);return this.fog!==null&&(t.object.fog=this.fog.toJSON()),t.object.backgroundBlurriness=this.backgroundBlurriness,t.object.backgroundIntensity=this.backgroundIntensity,t.object.backgroundRotation=this.backgroundRotation.toArray(),t.object.environmentIntensity=this.environmentIntensity,t.object.environmentRotation=this.environmentRotation.toArray(),t}},Ai=new W,hs=new W,Bh=new W,us=new W,Nr=new W,Ur=new W,If=new W,kh=new W,zh=new W,Vh=new W,Hh=new Ct,Gh=new Ct,Wh=new Ct,Fs=class i{constructor(e=new W,t=new W,n=new W){this.a=e,this.b=t,this.c=n}static getNormal(e,t,n,s){s.subVectors(n,t),Ai.subVectors(e,t),s.cross(Ai);let r=s.lengthSq();return r>0?s.multiplyScalar(1/Math.sqrt(r)):s.set(0,0,0)}static getBarycoord(e,t,n,s,r){Ai.subVectors(s,t),hs.subVectors(n,t),Bh.subVectors(e,t);let o=Ai.dot(Ai),a=Ai.dot(hs),c=Ai.dot(Bh),l=hs.dot(hs),d=hs.dot(Bh),u=o*l-a*a;if(u===0)return r.set(0,0,0),null;let h=1/u,m=(l*c-a*d)*h,g=(o*d-a*c)*h;return r.set(1-m-g,g,m)}static containsPoint(e,t,n,s){return this.getBarycoord(e,t,n,s,us)===null?!1:us.x>=0&&us.y>=0&&us.x+us.y<=1}static getInterpolation(e,t,n,s,r,o,a,c){return this.getBarycoord(e,t,n,s,us)===null?(c.x=0,c.y=0,"z"in c&&(c.z=0),"w"in c&&(c.w=0),null):(c.setScalar(0),c.addScaledVector(r,us.x),c.addScaledVector(o,us.y),c.addScaledVector(a,us.z),c)}static getInterpolatedAttribute(e,t,n,s,r,o){return Hh.setScalar(0),Gh.setScalar(0),Wh.setScalar(0),Hh.fromBufferAttribute(e,t),Gh.fromBufferAttribute(e,n),Wh.fromBufferAttribute(e,s),o.setScalar(0),o.addScaledVector(Hh,r.x),o.addScaledVector(Gh,r.y),o.addScaledVector(Wh,r.z),o}static isFrontFacing(e,t,n,s){return Ai.subVectors(n,t),hs.subVectors(e,t),Ai.cross(hs).dot(s)<0}set(e,t,n){return this.a.copy(e),this.b.copy(t),this.c.copy(n),this}setFromPointsAndIndices(e,t,n,s){return this.a.copy(e[t]),this.b.copy(e[n]),this.c.copy(e[s]),this}setFromAttributeAndIndices(e,t,n,s){return this.a.fromBufferAttribute(e,t),this.b.fromBufferAttribute(e,n),this.c.fromBufferAttribute(e,s),this}clone(){return new this.constructor().copy(this)}copy(e){return this.a.copy(e.a),this.b.copy(e.b),this.c.copy(e.c),this}getArea(){return Ai.subVectors(this.c,this.b),hs.subVectors(this.a,this.b),Ai.cross(hs).length()*.5}getMidpoint(e){return e.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(e){return i.getNormal(this.a,this.b,this.c,e)}getPlane(e){return e.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(e,t){return i.getBarycoord(e,this.a,this.b,this.c,t)}getInterpolation(e,t,n,s,r){return i.getInterpolation(e,this.a,this.b,this.c,t,n,s,r)}containsPoint(e){return i.containsPoint(e,this.a,this.b,this.c)}isFrontFacing(e){return i.isFrontFacing(this.a,this.b,this.c,e)}intersectsBox(e){return e.intersectsTriangle(this)}closestPointToPoint(e,t){let n=this.a,s=this.b,r=this.c,o,a;Nr.subVectors(s,n),Ur.subVectors(r,n),kh.subVectors(e,n);let c=Nr.dot(kh),l=Ur.dot(kh);if(c<=0&&l<=0)return t.copy(n);zh.subVectors(e,s);let d=Nr.dot(zh),u=Ur.dot(zh);if(d>=0&&u<=d)return t.copy(s);let h=c*u-d*l;if(h<=0&&c>=0&&d<=0&&c-d>0)return o=c/(c-d),t.copy(n).addScaledVector(Nr,o);Vh.subVectors(e,r);let m=Nr.dot(Vh),g=Ur.dot(Vh);if(g>=0&&m<=g)return t.copy(r);let v=m*l-c*g;if(v<=0&&l>=0&&g<=0)return a=l/(l-g),t.copy(n).addScaledVector(Ur,a);let p=d*g-m*u;if(p<=0&&u-d>=0&&m-g>=0)return If.subVectors(r,s),a=(u-d)/(u-d+(m-g)),t.copy(s).addScaledVector(If,a);let f=1/(p+v+h);return o=v*f,a=h*f,t.copy(n).addScaledVector(Nr,o).addScaledVector(Ur,a)}equals(e){return e.a.equals(this.a)&&e.b.equals(this.b)&&e.c.equals(this.c)}},qn=class{constructor(e=new W(1/0,1/0,1/0),t=new W(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=e,this.max=t}set(e,t){return this.min.copy(e),this.max.copy(t),this}setFromArray(e){this.makeEmpty();for(let t=0,n=e.length;t<n;t+=3)this.expandByPoint(Ri.fromArray(e,t));return this}setFromBufferAttribute(e){this.makeEmpty();for(let t=0,n=e.count;t<n;t++)this.expandByPoint(Ri.fromBufferAttribute(e,t));return this}setFromPoints(e){this.makeEmpty();for(let t=0,n=e.length;t<n;t++)this.expandByPoint(e[t]);return this}setFromCenterAndSize(e,t){let n=Ri.copy(t).multiplyScalar(.5);return this.min.copy(e).sub(n),this.max.copy(e).add(n),this}setFromObject(e,t=!1){return this.makeEmpty(),this.expandByObject(e,t)}clone(){return new this.constructor().copy(this)}copy(e){return this.min.copy(e.min),this.max.copy(e.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(e){return this.isEmpty()?e.set(0,0,0):e.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(e){return this.isEmpty()?e.set(0,0,0):e.subVectors(this.max,this.min)}expandByPoint(e){return this.min.min(e),this.max.max(e),this}expandByVector(e){return this.min.sub(e),this.max.add(e),this}expandByScalar(e){return this.min.addScalar(-e),this.max.addScalar(e),this}expandByObject(e,t=!1){e.updateWorldMatrix(!1,!1);let n=e.geometry;if(n!==void 0){let r=n.getAttribute("position");if(t===!0&&r!==void 0&&e.isInstancedMesh!==!0&&e.isBatchedMesh!==!0)for(let o=0,a=r.count;o<a;o++)e.isMesh===!0?e.getVertexPosition(o,Ri):Ri.fromBufferAttribute(r,o),Ri.applyMatrix4(e.matrixWorld),this.expandByPoint(Ri);else e.boundingBox!==void 0?(e.boundingBox===null&&e.computeBoundingBox(),Ja.copy(e.boundingBox)):(n.boundingBox===null&&n.computeBoundingBox(),Ja.copy(n.boundingBox)),Ja.applyMatrix4(e.matrixWorld),this.union(Ja)}let s=e.children;for(let r=0,o=s.length;r<o;r++)this.expandByObject(s[r],t);return this}containsPoint(e){return e.x>=this.min.x&&e.x<=this.max.x&&e.y>=this.min.y&&e.y<=this.max.y&&e.z>=this.min.z&&e.z<=this.max.z}containsBox(e){return this.min.x<=e.min.x&&e.max.x<=this.max.x&&this.min.y<=e.min.y&&e.max.y<=this.max.y&&this.min.z<=e.min.z&&e.max.z<=this.max.z}getParameter(e,t){return t.set((e.x-this.min.x)/(this.max.x-this.min.x),(e.y-this.min.y)/(this.max.y-this.min.y),(e.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(e){return e.max.x>=this.min.x&&e.min.x<=this.max.x&&e.max.y>=this.min.y&&e.min.y<=this.max.y&&e.max.z>=this.min.z&&e.min.z<=this.max.z}intersectsSphere(e){return this.clampPoint(e.center,Ri),Ri.distanceToSquared(e.center)<=e.radius*e.radius}intersectsPlane(e){let t,n;return e.normal.x>0?(t=e.normal.x*this.min.x,n=e.normal.x*this.max.x):(t=e.normal.x*this.max.x,n=e.normal.x*this.min.x),e.normal.y>0?(t+=e.normal.y*this.min.y,n+=e.normal.y*this.max.y):(t+=e.normal.y*this.max.y,n+=e.normal.y*this.min.y),e.normal.z>0?(t+=e.normal.z*this.min.z,n+=e.normal.z*this.max.z):(t+=e.normal.z*this.max.z,n+=e.normal.z*this.min.z),t<=-e.constant&&n>=-e.constant}intersectsTriangle(e){if(this.isEmpty())return!1;this.getCenter(Oo),Ka.subVectors(this.max,Oo),Fr.subVectors(e.a,Oo),Or.subVectors(e.b,Oo),Br.subVectors(e.c,Oo),Ds.subVectors(Or,Fr),Ns.subVectors(Br,Or),Qs.subVectors(Fr,Br);let t=[0,-Ds.z,Ds.y,0,-Ns.z,Ns.y,0,-Qs.z,Qs.y,Ds.z,0,-Ds.x,Ns.z,0,-Ns.x,Qs.z,0,-Qs.x,-Ds.y,Ds.x,0,-Ns.y,Ns.x,0,-Qs.y,Qs.x,0];return!$h(t,Fr,Or,Br,Ka)||(t=[1,0,0,0,1,0,0,0,1],!$h(t,Fr,Or,Br,Ka))?!1:(ja.crossVectors(Ds,Ns),t=[ja.x,ja.y,ja.z],$h(t,Fr,Or,Br,Ka))}clampPoint(e,t){return t.copy(e).clamp(this.min,this.max)}distanceToPoint(e){return this.clampPoint(e,Ri).distanceTo(e)}getBoundingSphere(e){return this.isEmpty()?e.makeEmpty():(this.getCenter(e.center),e.radius=this.getSize(Ri).length()*.5),e}intersect(e){return this.min.max(e.min),this.max.min(e.max),this.isEmpty()&&this.makeEmpty(),this}union(e){return this.min.min(e.min),this.max.max(e.max),this}applyMatrix4(e){return this.isEmpty()?this:(ds[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(e),ds[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(e),ds[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(e),ds[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(e),ds[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(e),ds[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(e),ds[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(e),ds[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(e),this.setFromPoints(ds),this)}translate(e){return this.min.add(e),this.max.add(e),this}equals(e){return e.min.equals(this.min)&&e.max.equals(this.max)}toJSON(){return{min:this.min.toArray(),max:this.max.toArray()}}fromJSON(e){return this.min.fromArray(e.min),this.max.fromArray(e.max),this}},ds=[new W,new W,new W,new W,new W,new W,new W,new W],Ri=new W,Ja=new qn,Fr=new W,Or=new W,Br=new W,Ds=new W,Ns=new W,Qs=new W,Oo=new W,Ka=new W,ja=new W,er=new W;function $h(i,e,t,n,s){for(let r=0,o=i.length-3;r<=o;r+=3){er.fromArray(i,r);let a=s.x*Math.abs(er.x)+s.y*Math.abs(er.y)+s.z*Math.abs(er.z),c=e.dot(er),l=t.dot(er),d=n.dot(er);if(Math.max(-Math.max(c,l,d),Math.min(c,l,d))>a)return!1}return!0}var hn=new W,Qa=new je,d_=0,Kn=class extends Ci{constructor(e,t,n=!1){if(super(),Array.isArray(e))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,Object.defineProperty(this,"id",{value:d_++}),this.name="",this.array=e,this.itemSize=t,this.count=e!==void 0?e.length/t:0,this.normalized=n,this.usage=Lu,this.updateRanges=[],this.gpuType=Di,this.version=0,this._normalizationScale=e!==void 0?Bc(e):void 0}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.name=e.name,this.array=new e.array.constructor(e.array),this.itemSize=e.itemSize,this.count=e.count,this.normalized=e.normalized,this.usage=e.usage,this.gpuType=e.gpuType,this._normalizationScale=e._normalizationScale,this}copyAt(e,t,n){e*=this.itemSize,n*=t.itemSize;for(let s=0,r=this.itemSize;s<r;s++)this.array[e+s]=t.array[n+s];return this}copyArray(e){return this.array.set(e),this}applyMatrix3(e){if(this.itemSize===2)for(let t=0,n=this.count;t<n;t++)Qa.fromBufferAttribute(this,t),Qa.applyMatrix3(e),this.setXY(t,Qa.x,Qa.y);else if(this.itemSize===3)for(let t=0,n=this.count;t<n;t++)hn.fromBufferAttribute(this,t),hn.applyMatrix3(e),this.setXYZ(t,hn.x,hn.y,hn.z);return this}applyMatrix4(e){for(let t=0,n=this.count;t<n;t++)hn.fromBufferAttribute(this,t),hn.applyMatrix4(e),this.setXYZ(t,hn.x,hn.y,hn.z);return this}applyNormalMatrix(e){for(let t=0,n=this.count;t<n;t++)hn.fromBufferAttribute(this,t),hn.applyNormalMatrix(e),this.setXYZ(t,hn.x,hn.y,hn.z);return this}transformDirection(e){for(let t=0,n=this.count;t<n;t++)hn.fromBufferAttribute(this,t),hn.transformDirection(e),this.setXYZ(t,hn.x,hn.y,hn.z);return this}set(e,t=0){return this.array.set(e,t),this}getComponent(e,t){let n=this.array[e*this.itemSize+t];return this.normalized&&(n=this._denormalize(n)),n}setComponent(e,t,n){return this.normalized&&(n=this._normalize(n)),this.array[e*this.itemSize+t]=n,this}getX(e){let t=this.array[e*this.itemSize];return this.normalized&&(t=this._denormalize(t)),t}setX(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize]=t,this}getY(e){let t=this.array[e*this.itemSize+1];return this.normalized&&(t=this._denormalize(t)),t}setY(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+1]=t,this}getZ(e){let t=this.array[e*this.itemSize+2];return this.normalized&&(t=this._denormalize(t)),t}setZ(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+2]=t,this}getW(e){let t=this.array[e*this.itemSize+3];return this.normalized&&(t=this._denormalize(t)),t}setW(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+3]=t,this}setXY(e,t,n){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),n=this._normalize(n)),this.array[e+0]=t,this.array[e+1]=n,this}setXYZ(e,t,n,s){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s)),this.array[e+0]=t,this.array[e+1]=n,this.array[e+2]=s,this}setXYZW(e,t,n,s,r){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s),r=this._normalize(r)),this.array[e+0]=t,this.array[e+1]=n,this.array[e+2]=s,this.array[e+3]=r,this}onUpload(e){return this.onUploadCallback=e,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){let e={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return e.name=this.name,e.usage=this.usage,e.gpuType=this.gpuType,e}dispose(){this.dispatchEvent({type:"dispose"})}_denormalize(e){let t=this._normalizationScale;return t!==void 0?Math.max(e/t,-1):Fu(e,this.array)}_normalize(e){let t=this._normalizationScale;return t!==void 0?Math.round(e*t):Ou(e,this.array)}};var jo=class extends Kn{constructor(e,t,n){super(new Uint16Array(e),t,n)}};var Qo=class extends Kn{constructor(e,t,n){super(new Uint32Array(e),t,n)}};var Ot=class extends Kn{constructor(e,t,n){super(new Float32Array(e),t,n)}},f_=new qn,Bo=new W,Xh=new W,Pi=class{constructor(e=new W,t=-1){this.isSphere=!0,this.center=e,this.radius=t}set(e,t){return this.center.copy(e),this.radius=t,this}setFromPoints(e,t){let n=this.center;t!==void 0?n.copy(t):f_.setFromPoints(e).getCenter(n);let s=0;for(let r=0,o=e.length;r<o;r++)s=Math.max(s,n.distanceToSquared(e[r]));return this.radius=Math.sqrt(s),this}copy(e){return this.center.copy(e.center),this.radius=e.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(e){return e.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(e){return e.distanceTo(this.center)-this.radius}intersectsSphere(e){let t=this.radius+e.radius;return e.center.distanceToSquared(this.center)<=t*t}intersectsBox(e){return e.intersectsSphere(this)}intersectsPlane(e){return Math.abs(e.distanceToPoint(this.center))<=this.radius}clampPoint(e,t){let n=this.center.distanceToSquared(e);return t.copy(e),n>this.radius*this.radius&&(t.sub(this.center).normalize(),t.multiplyScalar(this.radius).add(this.center)),t}getBoundingBox(e){return this.isEmpty()?(e.makeEmpty(),e):(e.set(this.center,this.center),e.expandByScalar(this.radius),e)}applyMatrix4(e){return this.center.applyMatrix4(e),this.radius=this.radius*e.getMaxScaleOnAxis(),this}translate(e){return this.center.add(e),this}expandByPoint(e){if(this.isEmpty())return this.center.copy(e),this.radius=0,this;Bo.subVectors(e,this.center);let t=Bo.lengthSq();if(t>this.radius*this.radius){let n=Math.sqrt(t),s=(n-this.radius)*.5;this.center.addScaledVector(Bo,s/n),this.radius+=s}return this}union(e){return e.isEmpty()?this:this.isEmpty()?(this.copy(e),this):(this.center.equals(e.center)===!0?this.radius=Math.max(this.radius,e.radius):(Xh.subVectors(e.center,this.center).setLength(e.radius),this.expandByPoint(Bo.copy(e.center).add(Xh)),this.expandByPoint(Bo.copy(e.center).sub(Xh))),this)}equals(e){return e.center.equals(this.center)&&e.radius===this.radius}clone(){return new this.constructor().copy(this)}toJSON(){return{radius:this.radius,center:this.center.toArray()}}fromJSON(e){return this.radius=e.radius,this.center.fromArray(e.center),this}},p_=0,xi=new kt,qh=new Cn,kr=new W,ai=new qn,ko=new qn,En=new W,An=class i extends Ci{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:p_++}),this.uuid=Xs(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.indirectOffset=0,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={},this._transformed=!1}getIndex(){return this.index}setIndex(e){return Array.isArray(e)?this.index=new(k0(e)?Qo:jo)(e,1):this.index=e,this}setIndirect(e,t=0){return this.indirect=e,this.indirectOffset=t,this}getIndirect(){return this.indirect}getAttribute(e){return this.attributes[e]}setAttribute(e,t){return this.attributes[e]=t,this}deleteAttribute(e){return delete this.attributes[e],this}hasAttribute(e){return this.attributes[e]!==void 0}addGroup(e,t,n=0){this.groups.push({start:e,count:t,materialIndex:n})}clearGroups(){this.groups=[]}setDrawRange(e,t){this.drawRange.start=e,this.drawRange.count=t}applyMatrix4(e){let t=this.attributes.position;t!==void 0&&(t.applyMatrix4(e),t.needsUpdate=!0);let n=this.attributes.normal;if(n!==void 0){let r=new st().getNormalMatrix(e);n.applyNormalMatrix(r),n.needsUpdate=!0}let s=this.attributes.tangent;return s!==void 0&&(s.transformDirection(e),s.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this._transformed=!0,this}applyQuaternion(e){return xi.makeRotationFromQuaternion(e),this.applyMatrix4(xi),this}rotateX(e){return xi.makeRotationX(e),this.applyMatrix4(xi),this}rotateY(e){return xi.makeRotationY(e),this.applyMatrix4(xi),this}rotateZ(e){return xi.makeRotationZ(e),this.applyMatrix4(xi),this}translate(e,t,n){return xi.makeTranslation(e,t,n),this.applyMatrix4(xi),this}scale(e,t,n){return xi.makeScale(e,t,n),this.applyMatrix4(xi),this}lookAt(e){return qh.lookAt(e),qh.updateMatrix(),this.applyMatrix4(qh.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(kr).negate(),this.translate(kr.x,kr.y,kr.z),this}setFromPoints(e){let t=this.getAttribute("position");if(t===void 0){let n=[];for(let s=0,r=e.length;s<r;s++){let o=e[s];n.push(o.x,o.y,o.z||0)}this.setAttribute("position",new Ot(n,3))}else{let n=Math.min(e.length,t.count);for(let s=0;s<n;s++){let r=e[s];t.setXYZ(s,r.x,r.y,r.z||0)}e.length>t.count&&Ye("BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),t.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new qn);let e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){it("BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new W(-1/0,-1/0,-1/0),new W(1/0,1/0,1/0));return}if(e!==void 0){if(this.boundingBox.setFromBufferAttribute(e),t)for(let n=0,s=t.length;n<s;n++){let r=t[n];ai.setFromBufferAttribute(r),this.morphTargetsRelative?(En.addVectors(this.boundingBox.min,ai.min),this.boundingBox.expandByPoint(En),En.addVectors(this.boundingBox.max,ai.max),this.boundingBox.expandByPoint(En)):(this.boundingBox.expandByPoint(ai.min),this.boundingBox.expandByPoint(ai.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&it('BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new Pi);let e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){it("BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new W,1/0);return}if(e){let n=this.boundingSphere.center;if(ai.setFromBufferAttribute(e),t)for(let r=0,o=t.length;r<o;r++){let a=t[r];ko.setFromBufferAttribute(a),this.morphTargetsRelative?(En.addVectors(ai.min,ko.min),ai.expandByPoint(En),En.addVectors(ai.max,ko.max),ai.expandByPoint(En)):(ai.expandByPoint(ko.min),ai.expandByPoint(ko.max))}ai.getCenter(n);let s=0;for(let r=0,o=e.count;r<o;r++)En.fromBufferAttribute(e,r),s=Math.max(s,n.distanceToSquared(En));if(t)for(let r=0,o=t.length;r<o;r++){let a=t[r],c=this.morphTargetsRelative;for(let l=0,d=a.count;l<d;l++)En.fromBufferAttribute(a,l),c&&(kr.fromBufferAttribute(e,l),En.add(kr)),s=Math.max(s,n.distanceToSquared(En))}this.boundingSphere.radius=Math.sqrt(s),isNaN(this.boundingSphere.radius)&&it('BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){let e=this.index,t=this.attributes;if(e===null||t.position===void 0||t.normal===void 0||t.uv===void 0){it("BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}let n=t.position,s=t.normal,r=t.uv,o=this.getAttribute("tangent");(o===void 0||o.count!==n.count)&&(o=new Kn(new Float32Array(4*n.count),4),this.setAttribute("tangent",o));let a=[],c=[],l=new Uint8Array(n.count);for(let H=0;H<n.count;H++)a[H]=new W,c[H]=new W;let d=new W,u=new W,h=new W,m=new je,g=new je,v=new je,p=new W,f=new W;function y(H,O,T){l[H]=l[O]=l[T]=1,d.fromBufferAttribute(n,H),u.fromBufferAttribute(n,O),h.fromBufferAttribute(n,T),m.fromBufferAttribute(r,H),g.fromBufferAttribute(r,O),v.fromBufferAttribute(r,T),u.sub(d),h.sub(d),g.sub(m),v.sub(m);let F=1/(g.x*v.y-v.x*g.y);isFinite(F)&&(p.copy(u).multiplyScalar(v.y).addScaledVector(h,-g.y).multiplyScalar(F),f.copy(h).multiplyScalar(g.x).addScaledVector(u,-v.x).multiplyScalar(F),a[H].add(p),a[O].add(p),a[T].add(p),c[H].add(f),c[O].add(f),c[T].add(f))}let C=this.groups;C.length===0&&(C=[{start:0,count:e.count}]);for(let H=0,O=C.length;H<O;++H){let T=C[H],F=T.start,B=T.count;for(let D=F,V=F+B;D<V;D+=3)y(e.getX(D+0),e.getX(D+1),e.getX(D+2))}let M=new W,R=new W,b=new W,_=new W;function A(H){b.fromBufferAttribute(s,H),_.copy(b);let O=a[H];M.copy(O),M.sub(b.multiplyScalar(b.dot(O))).normalize(),R.crossVectors(_,O);let F=R.dot(c[H])<0?-1:1;o.setXYZW(H,M.x,M.y,M.z,F)}for(let H=0,O=n.count;H<O;++H)l[H]&&A(H);this._transformed=!0}computeVertexNormals(){let e=this.index,t=this.getAttribute("position");if(t!==void 0){let n=this.getAttribute("normal");if(n===void 0||n.count!==t.count)n=new Kn(new Float32Array(t.count*3),3),this.setAttribute("normal",n);else for(let h=0,m=n.count;h<m;h++)n.setXYZ(h,0,0,0);let s=new W,r=new W,o=new W,a=new W,c=new W,l=new W,d=new W,u=new W;if(e)for(let h=0,m=e.count;h<m;h+=3){let g=e.getX(h+0),v=e.getX(h+1),p=e.getX(h+2);s.fromBufferAttribute(t,g),r.fromBufferAttribute(t,v),o.fromBufferAttribute(t,p),d.subVectors(o,r),u.subVectors(s,r),d.cross(u),a.fromBufferAttribute(n,g),c.fromBufferAttribute(n,v),l.fromBufferAttribute(n,p),a.add(d),c.add(d),l.add(d),n.setXYZ(g,a.x,a.y,a.z),n.setXYZ(v,c.x,c.y,c.z),n.setXYZ(p,l.x,l.y,l.z)}else for(let h=0,m=t.count;h<m;h+=3)s.fromBufferAttribute(t,h+0),r.fromBufferAttribute(t,h+1),o.fromBufferAttribute(t,h+2),d.subVectors(o,r),u.subVectors(s,r),d.cross(u),n.setXYZ(h+0,d.x,d.y,d.z),n.setXYZ(h+1,d.x,d.y,d.z),n.setXYZ(h+2,d.x,d.y,d.z);this.normalizeNormals(),n.needsUpdate=!0}}normalizeNormals(){let e=this.attributes.normal;for(let t=0,n=e.count;t<n;t++)En.fromBufferAttribute(e,t),En.normalize(),e.setXYZ(t,En.x,En.y,En.z)}toNonIndexed(){function e(a,c){let l=a.array,d=a.itemSize,u=a.normalized,h=new l.constructor(c.length*d),m=0,g=0;for(let v=0,p=c.length;v<p;v++){a.isInterleavedBufferAttribute?m=c[v]*a.data.stride+a.offset:m=c[v]*d;for(let f=0;f<d;f++)h[g++]=l[m++]}return new Kn(h,d,u)}if(this.index===null)return Ye("BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;let t=new i,n=this.index.array,s=this.attributes;for(let a in s){let c=s[a],l=e(c,n);t.setAttribute(a,l)}let r=this.morphAttributes;for(let a in r){let c=[],l=r[a];for(let d=0,u=l.length;d<u;d++){let h=l[d],m=e(h,n);c.push(m)}t.morphAttributes[a]=c}t.morphTargetsRelative=this.morphTargetsRelative;let o=this.groups;for(let a=0,c=o.length;a<c;a++){let l=o[a];t.addGroup(l.start,l.count,l.materialIndex)}return t}toJSON(){let e={metadata:{version:4.7,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(e.uuid=this.uuid,e.type=this.parameters!==void 0&&this._transformed===!0?"BufferGeometry":this.type,e.name=this.name,Object.keys(this.userData).length>0&&(e.userData=this.userData),this.parameters!==void 0&&this._transformed!==!0){let c=this.parameters;for(let l in c)c[l]!==void 0&&(e[l]=c[l]);return e}e.data={attributes:{}};let t=this.index;t!==null&&(e.data.index={type:t.array.constructor.name,array:Array.prototype.slice.call(t.array)});let n=this.attributes;for(let c in n){let l=n[c];e.data.attributes[c]=l.toJSON(e.data)}let s={},r=!1;for(let c in this.morphAttributes){let l=this.morphAttributes[c],d=[];for(let u=0,h=l.length;u<h;u++){let m=l[u];d.push(m.toJSON(e.data))}d.length>0&&(s[c]=d,r=!0)}r&&(e.data.morphAttributes=s,e.data.morphTargetsRelative=this.morphTargetsRelative);let o=this.groups;o.length>0&&(e.data.groups=JSON.parse(JSON.stringify(o)));let a=this.boundingSphere;return a!==null&&(e.data.boundingSphere=a.toJSON()),e}clone(){return new this.constructor().copy(this)}copy(e){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;let t={};this.name=e.name;let n=e.index;n!==null&&this.setIndex(n.clone());let s=e.attributes;for(let l in s){let d=s[l];this.setAttribute(l,d.clone(t))}let r=e.morphAttributes;for(let l in r){let d=[],u=r[l];for(let h=0,m=u.length;h<m;h++)d.push(u[h].clone(t));this.morphAttributes[l]=d}this.morphTargetsRelative=e.morphTargetsRelative;let o=e.groups;for(let l=0,d=o.length;l<d;l++){let u=o[l];this.addGroup(u.start,u.count,u.materialIndex)}let a=e.boundingBox;a!==null&&(this.boundingBox=a.clone());let c=e.boundingSphere;return c!==null&&(this.boundingSphere=c.clone()),this.drawRange.start=e.drawRange.start,this.drawRange.count=e.drawRange.count,this.userData=e.userData,this._transformed=e._transformed,this}dispose(){this.dispatchEvent({type:"dispose"})}},Il=class{constructor(e,t){this.isInterleavedBuffer=!0,this.array=e,this.stride=t,this.count=e!==void 0?e.length/t:0,this.usage=Lu,this.updateRanges=[],this.version=0,this.uuid=Xs()}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.array=new e.array.constructor(e.array),this.count=e.count,this.stride=e.stride,this.usage=e.usage,this}copyAt(e,t,n){e*=this.stride,n*=t.stride;for(let s=0,r=this.stride;s<r;s++)this.array[e+s]=t.array[n+s];return this}set(e,t=0){return this.array.set(e,t),this}clone(e){e.arrayBuffers===void 0&&(e.arrayBuffers={});let t=Lf(this.array);e.arrayBuffers[t]===void 0&&(e.arrayBuffers[t]=this.array.slice(0).buffer);let n=new this.array.constructor(e.arrayBuffers[t]),s=new this.constructor(n,this.stride);return s.setUsage(this.usage),s}onUpload(e){return this.onUploadCallback=e,this}toJSON(e){e.arrayBuffers===void 0&&(e.arrayBuffers={});let t=Lf(this.array);e.arrayBuffers[t]===void 0&&(e.arrayBuffers[t]=Array.from(new Uint32Array(this.array.slice(0).buffer)));let n={uuid:this.uuid,buffer:t,type:this.array.constructor.name,stride:this.stride};return n.usage=this.usage,n}};function Lf(i){return i.buffer._uuid===void 0&&(i.buffer._uuid=Xs()),i.byteOffset===0&&i.byteLength===i.buffer.byteLength?i.buffer._uuid:i.buffer._uuid+":"+i.byteOffset+":"+i.byteLength}var Wn=new W,Ii=class i{constructor(e,t,n,s=!1){this.isInterleavedBufferAttribute=!0,this.name="",this.data=e,this.itemSize=t,this.offset=n,this.normalized=s,this._normalizationScale=e!==void 0?Bc(e.array):void 0}get count(){return this.data.count}get array(){return this.data.array}set needsUpdate(e){this.data.needsUpdate=e}applyMatrix4(e){for(let t=0,n=this.data.count;t<n;t++)Wn.fromBufferAttribute(this,t),Wn.applyMatrix4(e),this.setXYZ(t,Wn.x,Wn.y,Wn.z);return this}applyNormalMatrix(e){for(let t=0,n=this.count;t<n;t++)Wn.fromBufferAttribute(this,t),Wn.applyNormalMatrix(e),this.setXYZ(t,Wn.x,Wn.y,Wn.z);return this}transformDirection(e){for(let t=0,n=this.count;t<n;t++)Wn.fromBufferAttribute(this,t),Wn.transformDirection(e),this.setXYZ(t,Wn.x,Wn.y,Wn.z);return this}getComponent(e,t){let n=this.array[e*this.data.stride+this.offset+t];return this.normalized&&(n=this._denormalize(n)),n}setComponent(e,t,n){return this.normalized&&(n=this._normalize(n)),this.data.array[e*this.data.stride+this.offset+t]=n,this}setX(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset]=t,this}setY(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset+1]=t,this}setZ(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset+2]=t,this}setW(e,t){return this.normalized&&(t=this._normalize(t)),this.data.array[e*this.data.stride+this.offset+3]=t,this}getX(e){let t=this.data.array[e*this.data.stride+this.offset];return this.normalized&&(t=this._denormalize(t)),t}getY(e){let t=this.data.array[e*this.data.stride+this.offset+1];return this.normalized&&(t=this._denormalize(t)),t}getZ(e){let t=this.data.array[e*this.data.stride+this.offset+2];return this.normalized&&(t=this._denormalize(t)),t}getW(e){let t=this.data.array[e*this.data.stride+this.offset+3];return this.normalized&&(t=this._denormalize(t)),t}setXY(e,t,n){return e=e*this.data.stride+this.offset,this.normalized&&(t=this._normalize(t),n=this._normalize(n)),this.data.array[e+0]=t,this.data.array[e+1]=n,this}setXYZ(e,t,n,s){return e=e*this.data.stride+this.offset,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s)),this.data.array[e+0]=t,this.data.array[e+1]=n,this.data.array[e+2]=s,this}setXYZW(e,t,n,s,r){return e=e*this.data.stride+this.offset,this.normalized&&(t=this._normalize(t),n=this._normalize(n),s=this._normalize(s),r=this._normalize(r)),this.data.array[e+0]=t,this.data.array[e+1]=n,this.data.array[e+2]=s,this.data.array[e+3]=r,this}clone(e){if(e===void 0){Yo("InterleavedBufferAttribute.clone(): Cloning an interleaved buffer attribute will de-interleave buffer data.");let t=[];for(let n=0;n<this.count;n++){let s=n*this.data.stride+this.offset;for(let r=0;r<this.itemSize;r++)t.push(this.data.array[s+r])}return new Kn(new this.array.constructor(t),this.itemSize,this.normalized)}else return e.interleavedBuffers===void 0&&(e.interleavedBuffers={}),e.interleavedBuffers[this.data.uuid]===void 0&&(e.interleavedBuffers[this.data.uuid]=this.data.clone(e)),new i(e.interleavedBuffers[this.data.uuid],this.itemSize,this.offset,this.normalized)}toJSON(e){if(e===void 0){Yo("InterleavedBufferAttribute.toJSON(): Serializing an interleaved buffer attribute will de-interleave buffer data.");let t=[];for(let n=0;n<this.count;n++){let s=n*this.data.stride+this.offset;for(let r=0;r<this.itemSize;r++)t.push(this.data.array[s+r])}return{itemSize:this.itemSize,type:this.array.constructor.name,array:t,normalized:this.normalized}}else return e.interleavedBuffers===void 0&&(e.interleavedBuffers={}),e.interleavedBuffers[this.data.uuid]===void 0&&(e.interleavedBuffers[this.data.uuid]=this.data.toJSON(e)),{isInterleavedBufferAttribute:!0,itemSize:this.itemSize,data:this.data.uuid,offset:this.offset,normalized:this.normalized}}_denormalize(e){let t=this._normalizationScale;return t!==void 0?Math.max(e/t,-1):Fu(e,this.data.array)}_normalize(e){let t=this._normalizationScale;return t!==void 0?Math.round(e*t):Ou(e,this.data.array)}},Yh=new W,m_=new W,g_=new st,li=class{constructor(e=new W(1,0,0),t=0){this.isPlane=!0,this.normal=e,this.constant=t}set(e,t){return this.normal.copy(e),this.constant=t,this}setComponents(e,t,n,s){return this.normal.set(e,t,n),this.constant=s,this}setFromNormalAndCoplanarPoint(e,t){return this.normal.copy(e),this.constant=-t.dot(this.normal),this}setFromCoplanarPoints(e,t,n){let s=Yh.subVectors(n,t).cross(m_.subVectors(e,t)).normalize();return this.setFromNormalAndCoplanarPoint(s,e),this}copy(e){return this.normal.copy(e.normal),this.constant=e.constant,this}normalize(){let e=1/this.normal.length();return this.normal.multiplyScalar(e),this.constant*=e,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(e){return this.normal.dot(e)+this.constant}distanceToSphere(e){return this.distanceToPoint(e.center)-e.radius}projectPoint(e,t){return t.copy(e).addScaledVector(this.normal,-this.distanceToPoint(e))}intersectLine(e,t,n=!0){let s=e.delta(Yh),r=this.normal.dot(s);if(r===0)return this.distanceToPoint(e.start)===0?t.copy(e.start):null;let o=-(e.start.dot(this.normal)+this.constant)/r;return n===!0&&(o<0||o>1)?null:t.copy(e.start).addScaledVector(s,o)}intersectsLine(e){let t=this.distanceToPoint(e.start),n=this.distanceToPoint(e.end);return t<0&&n>0||n<0&&t>0}intersectsBox(e){return e.intersectsPlane(this)}intersectsSphere(e){return e.intersectsPlane(this)}coplanarPoint(e){return e.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(e,t){let n=t||g_.getNormalMatrix(e),s=this.coplanarPoint(Yh).applyMatrix4(e),r=this.normal.applyMatrix3(n).normalize();return this.constant=-s.dot(r),this}translate(e){return this.constant-=e.dot(this.normal),this}equals(e){return e.normal.equals(this.normal)&&e.constant===this.constant}clone(){return new this.constructor().copy(this)}toJSON(){return{normal:this.normal.toArray(),constant:this.constant}}fromJSON(e){return this.normal.fromArray(e.normal),this.constant=e.constant,this}},__=0,_s=class extends Ci{constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:__++}),this.uuid=Xs(),this.name="",this.type="Material",this.blending=io,this.side=Ws,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=uu,this.blendDst=du,this.blendEquation=ar,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new ct(0,0,0),this.blendAlpha=0,this.depthFunc=Xr,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=Sp,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=_l,this.stencilZFail=_l,this.stencilZPass=_l,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.allowOverride=!0,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(e){this._alphaTest>0!=e>0&&this.version++,this._alphaTest=e}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(e){if(e!==void 0)for(let t in e){let n=e[t];if(n===void 0){Ye(`Material: parameter '${t}' has value of undefined.`);continue}let s=this[t];if(s===void 0){Ye(`Material: '${t}' is not a property of THREE.${this.type}.`);continue}s&&s.isColor?s.set(n):s&&s.isVector2&&n&&n.isVector2||s&&s.isEuler&&n&&n.isEuler||s&&s.isVector3&&n&&n.isVector3?s.copy(n):this[t]=n}}toJSON(e){let t=e===void 0||typeof e=="string";t&&(e={textures:{},images:{}});let n={metadata:{version:4.7,type:"Material",generator:"Material.toJSON"}};n.uuid=this.uuid,n.type=this.type,n.blending=this.blending,n.side=this.side,n.shadowSide=this.shadowSide,n.vertexColors=this.vertexColors,n.opacity=this.opacity,n.transparent=this.transparent,n.blendSrc=this.blendSrc,n.blendDst=this.blendDst,n.blendEquation=this.blendEquation,n.blendSrcAlpha=this.blendSrcAlpha,n.blendDstAlpha=this.blendDstAlpha,n.blendEquationAlpha=this.blendEquationAlpha,n.blendColor=this.blendColor.getHex(),n.blendAlpha=this.blendAlpha,n.depthFunc=this.depthFunc,n.depthTest=this.depthTest,n.depthWrite=this.depthWrite,n.colorWrite=this.colorWrite,n.clipIntersection=this.clipIntersection,n.clipShadows=this.clipShadows,n.stencilWriteMask=this.stencilWriteMask,n.stencilFunc=this.stencilFunc,n.stencilRef=this.stencilRef,n.stencilFuncMask=this.stencilFuncMask,n.stencilFail=this.stencilFail,n.stencilZFail=this.stencilZFail,n.stencilZPass=this.stencilZPass,n.stencilWrite=this.stencilWrite,n.polygonOffset=this.polygonOffset,n.polygonOffsetFactor=this.polygonOffsetFactor,n.polygonOffsetUnits=this.polygonOffsetUnits,n.dithering=this.dithering,n.alphaTest=this.alphaTest,n.alphaHash=this.alphaHash,n.alphaToCoverage=this.alphaToCoverage,n.premultipliedAlpha=this.premultipliedAlpha,n.forceSinglePass=this.forceSinglePass,n.allowOverride=this.allowOverride,n.visible=this.visible,n.toneMapped=this.toneMapped,n.name=this.name,this.color&&this.color.isColor&&(n.color=this.color.getHex()),this.roughness!==void 0&&(n.roughness=this.roughness),this.metalness!==void 0&&(n.metalness=this.metalness),this.sheen!==void 0&&(n.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(n.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(n.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(n.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&(n.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(n.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(n.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(n.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(n.shininess=this.shininess),this.clearcoat!==void 0&&(n.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(n.clearcoatRoughness=this.clearcoatRoughness),this.diffuseRoughness!==void 0&&(n.diffuseRoughness=this.diffuseRoughness),this.diffuseRoughnessMap&&this.diffuseRoughnessMap.isTexture&&(n.diffuseRoughnessMap=this.diffuseRoughnessMap.toJSON(e).uuid),this.clearcoatMap&&this.clearcoatMap.isTexture&&(n.clearcoatMap=this.clearcoatMap.toJSON(e).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(n.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(e).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(n.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(e).uuid,n.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.sheenColorMap&&this.sheenColorMap.isTexture&&(n.sheenColorMap=this.sheenColorMap.toJSON(e).uuid),this.sheenRoughnessMap&&this.sheenRoughnessMap.isTexture&&(n.sheenRoughnessMap=this.sheenRoughnessMap.toJSON(e).uuid),this.dispersion!==void 0&&(n.dispersion=this.dispersion),this.retroreflectivity!==void 0&&(n.retroreflectivity=this.retroreflectivity),this.iridescence!==void 0&&(n.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(n.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessMinimum!==void 0&&(n.iridescenceThicknessMinimum=this.iridescenceThicknessMinimum),this.iridescenceThicknessMaximum!==void 0&&(n.iridescenceThicknessMaximum=this.iridescenceThicknessMaximum),this.iridescenceMap&&this.iridescenceMap.isTexture&&(n.iridescenceMap=this.iridescenceMap.toJSON(e).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(n.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(e).uuid),this.anisotropy!==void 0&&(n.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(n.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(n.anisotropyMap=this.anisotropyMap.toJSON(e).uuid),this.map&&this.map.isTexture&&(n.map=this.map.toJSON(e).uuid),this.matcap&&this.matcap.isTexture&&(n.matcap=this.matcap.toJSON(e).uuid),this.alphaMap&&this.alphaMap.isTexture&&(n.alphaMap=this.alphaMap.toJSON(e).uuid),this.lightMap&&this.lightMap.isTexture&&(n.lightMap=this.lightMap.toJSON(e).uuid,n.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(n.aoMap=this.aoMap.toJSON(e).uuid,n.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(n.bumpMap=this.bumpMap.toJSON(e).uuid,n.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(n.normalMap=this.normalMap.toJSON(e).uuid,n.normalMapType=this.normalMapType,n.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(n.displacementMap=this.displacementMap.toJSON(e).uuid,n.displacementScale=this.displacementScale,n.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(n.roughnessMap=this.roughnessMap.toJSON(e).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(n.metalnessMap=this.metalnessMap.toJSON(e).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(n.emissiveMap=this.emissiveMap.toJSON(e).uuid),this.specularMap&&this.specularMap.isTexture&&(n.specularMap=this.specularMap.toJSON(e).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(n.specularIntensityMap=this.specularIntensityMap.toJSON(e).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(n.specularColorMap=this.specularColorMap.toJSON(e).uuid),this.envMap&&this.envMap.isTexture&&(n.envMap=this.envMap.toJSON(e).uuid,this.combine!==void 0&&(n.combine=this.combine)),this.envMapRotation!==void 0&&(n.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(n.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(n.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(n.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(n.gradientMap=this.gradientMap.toJSON(e).uuid),this.transmission!==void 0&&(n.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(n.transmissionMap=this.transmissionMap.toJSON(e).uuid),this.thickness!==void 0&&(n.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(n.thicknessMap=this.thicknessMap.toJSON(e).uuid),this.attenuationDistance!==void 0&&(n.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(n.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(n.size=this.size),this.sizeAttenuation!==void 0&&(n.sizeAttenuation=this.sizeAttenuation),Array.isArray(this.clippingPlanes)&&this.clippingPlanes.length>0&&(n.clippingPlanes=this.clippingPlanes.map(r=>r.toJSON())),this.rotation!==void 0&&(n.rotation=this.rotation),this.depthPacking!==void 0&&(n.depthPacking=this.depthPacking),this.linewidth!==void 0&&(n.linewidth=this.linewidth),this.linecap!==void 0&&(n.linecap=this.linecap),this.linejoin!==void 0&&(n.linejoin=this.linejoin),this.dashSize!==void 0&&(n.dashSize=this.dashSize),this.gapSize!==void 0&&(n.gapSize=this.gapSize),this.scale!==void 0&&(n.scale=this.scale),this.wireframe!==void 0&&(n.wireframe=this.wireframe),this.wireframeLinewidth!==void 0&&(n.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!==void 0&&(n.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!==void 0&&(n.wireframeLinejoin=this.wireframeLinejoin),this.flatShading!==void 0&&(n.flatShading=this.flatShading),this.fog!==void 0&&(n.fog=this.fog),Object.keys(this.userData).length>0&&(n.userData=this.userData);function s(r){let o=[];for(let a in r){let c=r[a];delete c.metadata,o.push(c)}return o}if(t){let r=s(e.textures),o=s(e.images);r.length>0&&(n.textures=r),o.length>0&&(n.images=o)}return n}fromJSON(e,t){if(e.uuid!==void 0&&(this.uuid=e.uuid),e.name!==void 0&&(this.name=e.name),e.color!==void 0&&this.color!==void 0&&this.color.setHex(e.color),e.roughness!==void 0&&(this.roughness=e.roughness),e.metalness!==void 0&&(this.metalness=e.metalness),e.sheen!==void 0&&(this.sheen=e.sheen),e.sheenColor!==void 0&&(this.sheenColor=new ct().setHex(e.sheenColor)),e.sheenRoughness!==void 0&&(this.sheenRoughness=e.sheenRoughness),e.emissive!==void 0&&this.emissive!==void 0&&this.emissive.setHex(e.emissive),e.specular!==void 0&&this.specular!==void 0&&this.specular.setHex(e.specular),e.specularIntensity!==void 0&&(this.specularIntensity=e.specularIntensity),e.specularColor!==void 0&&this.specularColor!==void 0&&this.specularColor.setHex(e.specularColor),e.shininess!==void 0&&(this.shininess=e.shininess),e.clearcoat!==void 0&&(this.clearcoat=e.clearcoat),e.clearcoatRoughness!==void 0&&(this.clearcoatRoughness=e.clearcoatRoughness),e.diffuseRoughness!==void 0&&(this.diffuseRoughness=e.diffuseRoughness),e.dispersion!==void 0&&(this.dispersion=e.dispersion),e.retroreflectivity!==void 0&&(this.retroreflectivity=e.retroreflectivity),e.iridescence!==void 0&&(this.iridescence=e.iridescence),e.iridescenceIOR!==void 0&&(this.iridescenceIOR=e.iridescenceIOR),e.iridescenceThicknessMinimum!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessMinimum),e.iridescenceThicknessMaximum!==void 0&&(this.iridescenceThicknessMaximum=e.iridescenceThicknessMaximum),e.iridescenceThicknessRange!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessRange[0],this.iridescenceThicknessMaximum=e.iridescenceThicknessRange[1]),e.transmission!==void 0&&(this.transmission=e.transmission),e.thickness!==void 0&&(this.thickness=e.thickness),e.attenuationDistance!==void 0&&(this.attenuationDistance=e.attenuationDistance),e.attenuationColor!==void 0&&this.attenuationColor!==void 0&&this.attenuationColor.setHex(e.attenuationColor),e.anisotropy!==void 0&&(this.anisotropy=e.anisotropy),e.anisotropyRotation!==void 0&&(this.anisotropyRotation=e.anisotropyRotation),e.fog!==void 0&&(this.fog=e.fog),e.flatShading!==void 0&&(this.flatShading=e.flatShading),e.blending!==void 0&&(this.blending=e.blending),e.combine!==void 0&&(this.combine=e.combine),e.side!==void 0&&(this.side=e.side),e.shadowSide!==void 0&&(this.shadowSide=e.shadowSide),e.opacity!==void 0&&(this.opacity=e.opacity),e.transparent!==void 0&&(this.transparent=e.transparent),e.alphaTest!==void 0&&(this.alphaTest=e.alphaTest),e.alphaHash!==void 0&&(this.alphaHash=e.alphaHash),e.depthFunc!==void 0&&(this.depthFunc=e.depthFunc),e.depthTest!==void 0&&(this.depthTest=e.depthTest),e.depthWrite!==void 0&&(this.depthWrite=e.depthWrite),e.colorWrite!==void 0&&(this.colorWrite=e.colorWrite),e.clippingPlanes!==void 0&&(this.clippingPlanes=e.clippingPlanes.map(n=>new li().fromJSON(n))),e.clipIntersection!==void 0&&(this.clipIntersection=e.clipIntersection),e.clipShadows!==void 0&&(this.clipShadows=e.clipShadows),e.depthPacking!==void 0&&(this.depthPacking=e.depthPacking),e.blendSrc!==void 0&&(this.blendSrc=e.blendSrc),e.blendDst!==void 0&&(this.blendDst=e.blendDst),e.blendEquation!==void 0&&(this.blendEquation=e.blendEquation),e.blendSrcAlpha!==void 0&&(this.blendSrcAlpha=e.blendSrcAlpha),e.blendDstAlpha!==void 0&&(this.blendDstAlpha=e.blendDstAlpha),e.blendEquationAlpha!==void 0&&(this.blendEquationAlpha=e.blendEquationAlpha),e.blendColor!==void 0&&this.blendColor!==void 0&&this.blendColor.setHex(e.blendColor),e.blendAlpha!==void 0&&(this.blendAlpha=e.blendAlpha),e.stencilWriteMask!==void 0&&(this.stencilWriteMask=e.stencilWriteMask),e.stencilFunc!==void 0&&(this.stencilFunc=e.stencilFunc),e.stencilRef!==void 0&&(this.stencilRef=e.stencilRef),e.stencilFuncMask!==void 0&&(this.stencilFuncMask=e.stencilFuncMask),e.stencilFail!==void 0&&(this.stencilFail=e.stencilFail),e.stencilZFail!==void 0&&(this.stencilZFail=e.stencilZFail),e.stencilZPass!==void 0&&(this.stencilZPass=e.stencilZPass),e.stencilWrite!==void 0&&(this.stencilWrite=e.stencilWrite),e.wireframe!==void 0&&(this.wireframe=e.wireframe),e.wireframeLinewidth!==void 0&&(this.wireframeLinewidth=e.wireframeLinewidth),e.wireframeLinecap!==void 0&&(this.wireframeLinecap=e.wireframeLinecap),e.wireframeLinejoin!==void 0&&(this.wireframeLinejoin=e.wireframeLinejoin),e.rotation!==void 0&&(this.rotation=e.rotation),e.linewidth!==void 0&&(this.linewidth=e.linewidth),e.linecap!==void 0&&(this.linecap=e.linecap),e.linejoin!==void 0&&(this.linejoin=e.linejoin),e.dashSize!==void 0&&(this.dashSize=e.dashSize),e.gapSize!==void 0&&(this.gapSize=e.gapSize),e.scale!==void 0&&(this.scale=e.scale),e.polygonOffset!==void 0&&(this.polygonOffset=e.polygonOffset),e.polygonOffsetFactor!==void 0&&(this.polygonOffsetFactor=e.polygonOffsetFactor),e.polygonOffsetUnits!==void 0&&(this.polygonOffsetUnits=e.polygonOffsetUnits),e.dithering!==void 0&&(this.dithering=e.dithering),e.alphaToCoverage!==void 0&&(this.alphaToCoverage=e.alphaToCoverage),e.premultipliedAlpha!==void 0&&(this.premultipliedAlpha=e.premultipliedAlpha),e.forceSinglePass!==void 0&&(this.forceSinglePass=e.forceSinglePass),e.allowOverride!==void 0&&(this.allowOverride=e.allowOverride),e.visible!==void 0&&(this.visible=e.visible),e.toneMapped!==void 0&&(this.toneMapped=e.toneMapped),e.userData!==void 0&&(this.userData=e.userData),e.vertexColors!==void 0&&(typeof e.vertexColors=="number"?this.vertexColors=e.vertexColors>0:this.vertexColors=e.vertexColors),e.size!==void 0&&(this.size=e.size),e.sizeAttenuation!==void 0&&(this.sizeAttenuation=e.sizeAttenuation),e.map!==void 0&&(this.map=t[e.map]||null),e.matcap!==void 0&&(this.matcap=t[e.matcap]||null),e.alphaMap!==void 0&&(this.alphaMap=t[e.alphaMap]||null),e.bumpMap!==void 0&&(this.bumpMap=t[e.bumpMap]||null),e.bumpScale!==void 0&&(this.bumpScale=e.bumpScale),e.normalMap!==void 0&&(this.normalMap=t[e.normalMap]||null),e.normalMapType!==void 0&&(this.normalMapType=e.normalMapType),e.normalScale!==void 0){let n=e.normalScale;Array.isArray(n)===!1&&(n=[n,n]),this.normalScale=new je().fromArray(n)}return e.displacementMap!==void 0&&(this.displacementMap=t[e.displacementMap]||null),e.displacementScale!==void 0&&(this.displacementScale=e.displacementScale),e.displacementBias!==void 0&&(this.displacementBias=e.displacementBias),e.roughnessMap!==void 0&&(this.roughnessMap=t[e.roughnessMap]||null),e.metalnessMap!==void 0&&(this.metalnessMap=t[e.metalnessMap]||null),e.emissiveMap!==void 0&&(this.emissiveMap=t[e.emissiveMap]||null),e.emissiveIntensity!==void 0&&(this.emissiveIntensity=e.emissiveIntensity),e.specularMap!==void 0&&(this.specularMap=t[e.specularMap]||null),e.specularIntensityMap!==void 0&&(this.specularIntensityMap=t[e.specularIntensityMap]||null),e.specularColorMap!==void 0&&(this.specularColorMap=t[e.specularColorMap]||null),e.envMap!==void 0&&(this.envMap=t[e.envMap]||null),e.envMapRotation!==void 0&&this.envMapRotation.fromArray(e.envMapRotation),e.envMapIntensity!==void 0&&(this.envMapIntensity=e.envMapIntensity),e.reflectivity!==void 0&&(this.reflectivity=e.reflectivity),e.refractionRatio!==void 0&&(this.refractionRatio=e.refractionRatio),e.lightMap!==void 0&&(this.lightMap=t[e.lightMap]||null),e.lightMapIntensity!==void 0&&(this.lightMapIntensity=e.lightMapIntensity),e.aoMap!==void 0&&(this.aoMap=t[e.aoMap]||null),e.aoMapIntensity!==void 0&&(this.aoMapIntensity=e.aoMapIntensity),e.gradientMap!==void 0&&(this.gradientMap=t[e.gradientMap]||null),e.clearcoatMap!==void 0&&(this.clearcoatMap=t[e.clearcoatMap]||null),e.clearcoatRoughnessMap!==void 0&&(this.clearcoatRoughnessMap=t[e.clearcoatRoughnessMap]||null),e.clearcoatNormalMap!==void 0&&(this.clearcoatNormalMap=t[e.clearcoatNormalMap]||null),e.clearcoatNormalScale!==void 0&&(this.clearcoatNormalScale=new je().fromArray(e.clearcoatNormalScale)),e.diffuseRoughnessMap!==void 0&&(this.diffuseRoughnessMap=t[e.diffuseRoughnessMap]||null),e.iridescenceMap!==void 0&&(this.iridescenceMap=t[e.iridescenceMap]||null),e.iridescenceThicknessMap!==void 0&&(this.iridescenceThicknessMap=t[e.iridescenceThicknessMap]||null),e.transmissionMap!==void 0&&(this.transmissionMap=t[e.transmissionMap]||null),e.thicknessMap!==void 0&&(this.thicknessMap=t[e.thicknessMap]||null),e.anisotropyMap!==void 0&&(this.anisotropyMap=t[e.anisotropyMap]||null),e.sheenColorMap!==void 0&&(this.sheenColorMap=t[e.sheenColorMap]||null),e.sheenRoughnessMap!==void 0&&(this.sheenRoughnessMap=t[e.sheenRoughnessMap]||null),this}clone(){return new this.constructor().copy(this)}copy(e){this.name=e.name,this.blending=e.blending,this.side=e.side,this.vertexColors=e.vertexColors,this.opacity=e.opacity,this.transparent=e.transparent,this.blendSrc=e.blendSrc,this.blendDst=e.blendDst,this.blendEquation=e.blendEquation,this.blendSrcAlpha=e.blendSrcAlpha,this.blendDstAlpha=e.blendDstAlpha,this.blendEquationAlpha=e.blendEquationAlpha,this.blendColor.copy(e.blendColor),this.blendAlpha=e.blendAlpha,this.depthFunc=e.depthFunc,this.depthTest=e.depthTest,this.depthWrite=e.depthWrite,this.stencilWriteMask=e.stencilWriteMask,this.stencilFunc=e.stencilFunc,this.stencilRef=e.stencilRef,this.stencilFuncMask=e.stencilFuncMask,this.stencilFail=e.stencilFail,this.stencilZFail=e.stencilZFail,this.stencilZPass=e.stencilZPass,this.stencilWrite=e.stencilWrite;let t=e.clippingPlanes,n=null;if(t!==null){let s=t.length;n=new Array(s);for(let r=0;r!==s;++r)n[r]=t[r].clone()}return this.clippingPlanes=n,this.clipIntersection=e.clipIntersection,this.clipShadows=e.clipShadows,this.shadowSide=e.shadowSide,this.colorWrite=e.colorWrite,this.precision=e.precision,this.polygonOffset=e.polygonOffset,this.polygonOffsetFactor=e.polygonOffsetFactor,this.polygonOffsetUnits=e.polygonOffsetUnits,this.dithering=e.dithering,this.alphaTest=e.alphaTest,this.alphaHash=e.alphaHash,this.alphaToCoverage=e.alphaToCoverage,this.premultipliedAlpha=e.premultipliedAlpha,this.forceSinglePass=e.forceSinglePass,this.allowOverride=e.allowOverride,this.visible=e.visible,this.toneMapped=e.toneMapped,this.userData=JSON.parse(JSON.stringify(e.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(e){e===!0&&this.version++}};var fs=new W,Zh=new W,el=new W,tl=new W,ir=class{constructor(e=new W,t=new W(0,0,-1)){this.origin=e,this.direction=t}set(e,t){return this.origin.copy(e),this.direction.copy(t),this}copy(e){return this.origin.copy(e.origin),this.direction.copy(e.direction),this}at(e,t){return t.copy(this.origin).addScaledVector(this.direction,e)}lookAt(e){return this.direction.copy(e).sub(this.origin).normalize(),this}recast(e){return this.origin.copy(this.at(e,fs)),this}closestPointToPoint(e,t){t.subVectors(e,this.origin);let n=t.dot(this.direction);return n<0?t.copy(this.origin):t.copy(this.origin).addScaledVector(this.direction,n)}distanceToPoint(e){return Math.sqrt(this.distanceSqToPoint(e))}distanceSqToPoint(e){let t=fs.subVectors(e,this.origin).dot(this.direction);return t<0?this.origin.distanceToSquared(e):(fs.copy(this.origin).addScaledVector(this.direction,t),fs.distanceToSquared(e))}distanceSqToSegment(e,t,n,s){Zh.copy(e).add(t).multiplyScalar(.5),el.copy(t).sub(e).normalize(),tl.copy(this.origin).sub(Zh);let r=e.distanceTo(t)*.5,o=-this.direction.dot(el),a=tl.dot(this.direction),c=-tl.dot(el),l=tl.lengthSq(),d=Math.abs(1-o*o),u,h,m,g;if(d>0)if(u=o*c-a,h=o*a-c,g=r*d,u>=0)if(h>=-g)if(h<=g){let v=1/d;u*=v,h*=v,m=u*(u+o*h+2*a)+h*(o*u+h+2*c)+l}else h=r,u=Math.max(0,-(o*h+a)),m=-u*u+h*(h+2*c)+l;else h=-r,u=Math.max(0,-(o*h+a)),m=-u*u+h*(h+2*c)+l;else h<=-g?(u=Math.max(0,-(-o*r+a)),h=u>0?-r:Math.min(Math.max(-r,-c),r),m=-u*u+h*(h+2*c)+l):h<=g?(u=0,h=Math.min(Math.max(-r,-c),r),m=h*(h+2*c)+l):(u=Math.max(0,-(o*r+a)),h=u>0?r:Math.min(Math.max(-r,-c),r),m=-u*u+h*(h+2*c)+l);else h=o>0?-r:r,u=Math.max(0,-(o*h+a)),m=-u*u+h*(h+2*c)+l;return n&&n.copy(this.origin).addScaledVector(this.direction,u),s&&s.copy(Zh).addScaledVector(el,h),m}intersectSphere(e,t){if(e.radius<0)return null;fs.subVectors(e.center,this.origin);let n=fs.dot(this.direction),s=fs.dot(fs)-n*n,r=e.radius*e.radius;if(s>r)return null;let o=Math.sqrt(r-s),a=n-o,c=n+o;return c<0?null:a<0?this.at(c,t):this.at(a,t)}intersectsSphere(e){return e.radius<0?!1:this.distanceSqToPoint(e.center)<=e.radius*e.radius}distanceToPlane(e){let t=e.normal.dot(this.direction);if(t===0)return e.distanceToPoint(this.origin)===0?0:null;let n=-(this.origin.dot(e.normal)+e.constant)/t;return n>=0?n:null}intersectPlane(e,t){let n=this.distanceToPlane(e);return n===null?null:this.at(n,t)}intersectsPlane(e){let t=e.distanceToPoint(this.origin);return t===0||e.normal.dot(this.direction)*t<0}intersectBox(e,t){let n,s,r,o,a,c,l=1/this.direction.x,d=1/this.direction.y,u=1/this.direction.z,h=this.origin;return l>=0?(n=(e.min.x-h.x)*l,s=(e.max.x-h.x)*l):(n=(e.max.x-h.x)*l,s=(e.min.x-h.x)*l),d>=0?(r=(e.min.y-h.y)*d,o=(e.max.y-h.y)*d):(r=(e.max.y-h.y)*d,o=(e.min.y-h.y)*d),n>o||r>s||((r>n||isNaN(n))&&(n=r),(o<s||isNaN(s))&&(s=o),u>=0?(a=(e.min.z-h.z)*u,c=(e.max.z-h.z)*u):(a=(e.max.z-h.z)*u,c=(e.min.z-h.z)*u),n>c||a>s)||((a>n||n!==n)&&(n=a),(c<s||s!==s)&&(s=c),s<0)?null:this.at(n>=0?n:s,t)}intersectsBox(e){return this.intersectBox(e,fs)!==null}intersectTriangle(e,t,n,s,r){let o=this.origin,a=this.direction,c=a.x,l=a.y,d=a.z,u=e.x-o.x,h=e.y-o.y,m=e.z-o.z,g=t.x-o.x,v=t.y-o.y,p=t.z-o.z,f=n.x-o.x,y=n.y-o.y,C=n.z-o.z,M=Math.abs(c),R=Math.abs(l),b=Math.abs(d),_,A,H,O,T,F,B,D,V,Y,$,ce;if(M>=R&&M>=b?(H=c,F=u,V=g,ce=f,c>=0?(_=l,A=d,O=h,T=m,B=v,D=p,Y=y,$=C):(_=d,A=l,O=m,T=h,B=p,D=v,Y=C,$=y)):R>=b?(H=l,F=h,V=v,ce=y,l>=0?(_=d,A=c,O=m,T=u,B=p,D=g,Y=C,$=f):(_=c,A=d,O=u,T=m,B=g,D=p,Y=f,$=C)):(H=d,F=m,V=p,ce=C,d>=0?(_=c,A=l,O=u,T=h,B=g,D=v,Y=f,$=y):(_=l,A=c,O=h,T=u,B=v,D=g,Y=y,$=f)),H===0)return null;let P=_/H,I=A/H,q=1/H,ie=O-P*F,he=T-I*F,Q=B-P*V,fe=D-I*V,le=Y-P*ce,me=$-I*ce,pe=le*fe-me*Q,De=ie*me-he*le,Ze=Q*he-fe*ie;if(s){if(pe<0||De<0||Ze<0)return null}else if((pe<0||De<0||Ze<0)&&(pe>0||De>0||Ze>0))return null;let Ne=pe+De+Ze;if(Ne===0)return null;let qe=q*(pe*F+De*V+Ze*ce);return(Ne>0?qe<0:qe>0)?null:this.at(qe/Ne,r)}applyMatrix4(e){return this.origin.applyMatrix4(e),this.direction.transformDirection(e),this}equals(e){return e.origin.equals(this.origin)&&e.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}},jr=class extends _s{constructor(e){super(),this.isMeshBasicMaterial=!0,this.type="MeshBasicMaterial",this.color=new ct(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new gs,this.combine=fu,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.specularMap=e.specularMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.combine=e.combine,this.reflectivity=e.reflectivity,this.refractionRatio=e.refractionRatio,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.fog=e.fog,this}},Df=new kt,tr=new ir,nl=new Pi,Nf=new W,il=new W,sl=new W,rl=new W,Jh=new W,ol=new W,Uf=new W,al=new W,Pn=class extends Cn{constructor(e=new An,t=new jr){super(),this.isMesh=!0,this.type="Mesh",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.count=1,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}updateMorphTargets(){let t=this.geometry.morphAttributes,n=Object.keys(t);if(n.length>0){let s=t[n[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,o=s.length;r<o;r++){let a=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=r}}}}getVertexPosition(e,t){let n=this.geometry,s=n.attributes.position,r=n.morphAttributes.position,o=n.morphTargetsRelative;t.fromBufferAttribute(s,e);let a=this.morphTargetInfluences;if(r&&a){ol.set(0,0,0);for(let c=0,l=r.length;c<l;c++){let d=a[c],u=r[c];d!==0&&(Jh.fromBufferAttribute(u,e),o?ol.addScaledVector(Jh,d):ol.addScaledVector(Jh.sub(t),d))}t.add(ol)}return t}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let n=this.geometry,s=this.material,r=this.matrixWorld;s!==void 0&&(n.boundingSphere===null&&n.computeBoundingSphere(),nl.copy(n.boundingSphere),nl.applyMatrix4(r),tr.copy(e.ray).recast(e.near),!(nl.containsPoint(tr.origin)===!1&&(tr.intersectSphere(nl,Nf)===null||tr.origin.distanceToSquared(Nf)>(e.far-e.near)**2))&&(Df.copy(r).invert(),tr.copy(e.ray).applyMatrix4(Df),!(n.boundingBox!==null&&tr.intersectsBox(n.boundingBox)===!1)&&this._computeIntersections(e,t,tr)))}_computeIntersections(e,t,n){let s,r=this.geometry,o=this.material,a=r.index,c=r.attributes.position,l=r.attributes.uv,d=r.attributes.uv1,u=r.attributes.normal,h=r.groups,m=r.drawRange;if(a!==null)if(Array.isArray(o))for(let g=0,v=h.length;g<v;g++){let p=h[g],f=o[p.materialIndex],y=Math.max(p.start,m.start),C=Math.min(a.count,Math.min(p.start+p.count,m.start+m.count));for(let M=y,R=C;M<R;M+=3){let b=a.getX(M),_=a.getX(M+1),A=a.getX(M+2);s=ll(this,f,e,n,l,d,u,b,_,A),s&&(s.faceIndex=Math.floor(M/3),s.face.materialIndex=p.materialIndex,t.push(s))}}else{let g=Math.max(0,m.start),v=Math.min(a.count,m.start+m.count);for(let p=g,f=v;p<f;p+=3){let y=a.getX(p),C=a.getX(p+1),M=a.getX(p+2);s=ll(this,o,e,n,l,d,u,y,C,M),s&&(s.faceIndex=Math.floor(p/3),t.push(s))}}else if(c!==void 0)if(Array.isArray(o))for(let g=0,v=h.length;g<v;g++){let p=h[g],f=o[p.materialIndex],y=Math.max(p.start,m.start),C=Math.min(c.count,Math.min(p.start+p.count,m.start+m.count));for(let M=y,R=C;M<R;M+=3){let b=M,_=M+1,A=M+2;s=ll(this,f,e,n,l,d,u,b,_,A),s&&(s.faceIndex=Math.floor(M/3),s.face.materialIndex=p.materialIndex,t.push(s))}}else{let g=Math.max(0,m.start),v=Math.min(c.count,m.start+m.count);for(let p=g,f=v;p<f;p+=3){let y=p,C=p+1,M=p+2;s=ll(this,o,e,n,l,d,u,y,C,M),s&&(s.faceIndex=Math.floor(p/3),t.push(s))}}}};function x_(i,e,t,n,s,r,o,a){let c;if(e.side===Yn?c=n.intersectTriangle(o,r,s,!0,a):c=n.intersectTriangle(s,r,o,e.side===Ws,a),c===null)return null;al.copy(a),al.applyMatrix4(i.matrixWorld);let l=t.ray.origin.distanceTo(al);return l<t.near||l>t.far?null:{distance:l,point:al.clone(),object:i}}function ll(i,e,t,n,s,r,o,a,c,l){i.getVertexPosition(a,il),i.getVertexPosition(c,sl),i.getVertexPosition(l,rl);let d=x_(i,e,t,n,il,sl,rl,Uf);if(d){let u=new W;Fs.getBarycoord(Uf,il,sl,rl,u),s&&(d.uv=Fs.getInterpolatedAttribute(s,a,c,l,u,new je)),r&&(d.uv1=Fs.getInterpolatedAttribute(r,a,c,l,u,new je)),o&&(d.normal=Fs.getInterpolatedAttribute(o,a,c,l,u,new W),d.normal.dot(n.direction)>0&&d.normal.multiplyScalar(-1));let h={a,b:c,c:l,normal:new W,materialIndex:0};Fs.getNormal(il,sl,rl,h.normal),d.face=h,d.barycoord=u}return d}var Ll=class extends jn{constructor(e=null,t=1,n=1,s,r,o,a,c,l=Tn,d=Tn,u,h){super(null,o,a,c,l,d,s,r,u,h),this.isDataTexture=!0,this.image={data:e,width:t,height:n},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}};var nr=new Pi,v_=new je(.5,.5),cl=new W,Os=class{constructor(e=new li,t=new li,n=new li,s=new li,r=new li,o=new li){this.planes=[e,t,n,s,r,o]}set(e,t,n,s,r,o){let a=this.planes;return a[0].copy(e),a[1].copy(t),a[2].copy(n),a[3].copy(s),a[4].copy(r),a[5].copy(o),this}copy(e){let t=this.planes;for(let n=0;n<6;n++)t[n].copy(e.planes[n]);return this}setFromProjectionMatrix(e,t=vi,n=!1){let s=this.planes,r=e.elements,o=r[0],a=r[1],c=r[2],l=r[3],d=r[4],u=r[5],h=r[6],m=r[7],g=r[8],v=r[9],p=r[10],f=r[11],y=r[12],C=r[13],M=r[14],R=r[15];if(s[0].setComponents(l-o,m-d,f-g,R-y).normalize(),s[1].setComponents(l+o,m+d,f+g,R+y).normalize(),s[2].setComponents(l+a,m+u,f+v,R+C).normalize(),s[3].setComponents(l-a,m-u,f-v,R-C).normalize(),n)s[4].setComponents(c,h,p,M).normalize(),s[5].setComponents(l-c,m-h,f-p,R-M).normalize();else if(s[4].setComponents(l-c,m-h,f-p,R-M).normalize(),t===vi)s[5].setComponents(l+c,m+h,f+p,R+M).normalize();else if(t===qr)s[5].setComponents(c,h,p,M).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+t);return this}intersectsObject(e){if(e.boundingSphere!==void 0)e.boundingSphere===null&&e.computeBoundingSphere(),nr.copy(e.boundingSphere).applyMatrix4(e.matrixWorld);else{let t=e.geometry;t.boundingSphere===null&&t.computeBoundingSphere(),nr.copy(t.boundingSphere).applyMatrix4(e.matrixWorld)}return this.intersectsSphere(nr)}intersectsSprite(e){nr.center.set(0,0,0);let t=v_.distanceTo(e.center);return nr.radius=.7071067811865476+t,nr.applyMatrix4(e.matrixWorld),this.intersectsSphere(nr)}intersectsSphere(e){let t=this.planes,n=e.center,s=-e.radius;for(let r=0;r<6;r++)if(t[r].distanceToPoint(n)<s)return!1;return!0}intersectsBox(e){let t=this.planes;for(let n=0;n<6;n++){let s=t[n];if(cl.x=s.normal.x>0?e.max.x:e.min.x,cl.y=s.normal.y>0?e.max.y:e.min.y,cl.z=s.normal.z>0?e.max.z:e.min.z,s.distanceToPoint(cl)<0)return!1}return!0}containsPoint(e){let t=this.planes;for(let n=0;n<6;n++)if(t[n].distanceToPoint(e)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}},Ff=new kt,Dl=class i{constructor(){this.coordinateSystem=vi,this._frustums=[],this._count=0}setFromArrayCamera(e){let t=e.cameras,n=this._frustums;for(let s=0;s<t.length;s++){let r=t[s];Ff.multiplyMatrices(r.projectionMatrix,r.matrixWorldInverse),n[s]===void 0&&(n[s]=new Os),n[s].setFromProjectionMatrix(Ff,r.coordinateSystem,r.reversedDepth)}return this._count=t.length,this}getFrustum(e){return this._frustums[e]}intersectsObject(e){let t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsObject(e))return!0;return!1}intersectsSprite(e){let t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsSprite(e))return!0;return!1}intersectsSphere(e){let t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsSphere(e))return!0;return!1}intersectsBox(e){let t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].intersectsBox(e))return!0;return!1}containsPoint(e){let t=this._frustums;for(let n=0;n<this._count;n++)if(t[n].containsPoint(e))return!0;return!1}copy(e){this.coordinateSystem=e.coordinateSystem;let t=this._frustums,n=e._frustums;for(let s=0;s<e._count;s++)t[s]===void 0&&(t[s]=new Os),t[s].copy(n[s]);return this._count=e._count,this}clone(){return new i().copy(this)}};var xs=class extends _s{constructor(e){super(),this.isLineBasicMaterial=!0,this.type="LineBasicMaterial",this.color=new ct(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.linewidth=e.linewidth,this.linecap=e.linecap,this.linejoin=e.linejoin,this.fog=e.fog,this}},Nl=new W,Ul=new W,Of=new kt,zo=new ir,hl=new Pi,Kh=new W,Bf=new W,sr=class extends Cn{constructor(e=new An,t=new xs){super(),this.isLine=!0,this.type="Line",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}computeLineDistances(){let e=this.geometry;if(e.index===null){let t=e.attributes.position,n=[0];for(let s=1,r=t.count;s<r;s++)Nl.fromBufferAttribute(t,s-1),Ul.fromBufferAttribute(t,s),n[s]=n[s-1],n[s]+=Nl.distanceTo(Ul);e.setAttribute("lineDistance",new Ot(n,1))}else Ye("Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let n=this.geometry,s=this.matrixWorld,r=e.params.Line.threshold,o=n.drawRange;if(n.boundingSphere===null&&n.computeBoundingSphere(),hl.copy(n.boundingSphere),hl.applyMatrix4(s),hl.radius+=r,e.ray.intersectsSphere(hl)===!1)return;Of.copy(s).invert(),zo.copy(e.ray).applyMatrix4(Of);let a=r/((this.scale.x+this.scale.y+this.scale.z)/3),c=a*a,l=this.isLineSegments?2:1,d=n.index,h=n.attributes.position;if(d!==null){let m=Math.max(0,o.start),g=Math.min(d.count,o.start+o.count);for(let v=m,p=g-1;v<p;v+=l){let f=d.getX(v),y=d.getX(v+1),C=ul(this,e,zo,c,f,y,v);C&&t.push(C)}if(this.isLineLoop){let v=d.getX(g-1),p=d.getX(m),f=ul(this,e,zo,c,v,p,g-1);f&&t.push(f)}}else{let m=Math.max(0,o.start),g=Math.min(h.count,o.start+o.count);for(let v=m,p=g-1;v<p;v+=l){let f=ul(this,e,zo,c,v,v+1,v);f&&t.push(f)}if(this.isLineLoop){let v=ul(this,e,zo,c,g-1,m,g-1);v&&t.push(v)}}}updateMorphTargets(){let t=this.geometry.morphAttributes,n=Object.keys(t);if(n.length>0){let s=t[n[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,o=s.length;r<o;r++){let a=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=r}}}}};function ul(i,e,t,n,s,r,o){let a=i.geometry.attributes.position;if(Nl.fromBufferAttribute(a,s),Ul.fromBufferAttribute(a,r),t.distanceSqToSegment(Nl,Ul,Kh,Bf)>n)return;Kh.applyMatrix4(i.matrixWorld);let l=e.ray.origin.distanceTo(Kh);if(!(l<e.near||l>e.far))return{distance:l,point:Bf.clone().applyMatrix4(i.matrixWorld),index:o,face:null,faceIndex:null,barycoord:null,object:i}}var kf=new W,zf=new W,ea=class extends sr{constructor(e,t){super(e,t),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){let e=this.geometry;if(e.index===null){let t=e.attributes.position,n=[];for(let s=0,r=t.count;s<r;s+=2)kf.fromBufferAttribute(t,s),zf.fromBufferAttribute(t,s+1),n[s]=s===0?0:n[s-1],n[s+1]=n[s]+kf.distanceTo(zf);e.setAttribute("lineDistance",new Ot(n,1))}else Ye("LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}};var ta=class extends jn{constructor(e=[],t=lr,n,s,r,o,a,c,l,d){super(e,t,n,s,r,o,a,c,l,d),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(e){this.image=e}};var vs=class extends jn{constructor(e,t,n=Li,s,r,o,a=Tn,c=Tn,l,d=ms,u=1){if(d!==ms&&d!==bs)throw new Error("THREE.DepthTexture: format must be either THREE.DepthFormat or THREE.DepthStencilFormat");let h={width:e,height:t,depth:u};super(h,s,r,o,a,c,d,n,l),this.isDepthTexture=!0,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(e){return super.copy(e),this.source=new Jr(Object.assign({},e.image)),this.compareFunction=e.compareFunction,this}toJSON(e){let t=super.toJSON(e);return t.compareFunction=this.compareFunction,t}},na=class extends vs{constructor(e,t=Li,n=lr,s,r,o=Tn,a=Tn,c,l=ms){let d={width:e,height:e,depth:1},u=[d,d,d,d,d,d];super(e,e,t,n,s,r,o,a,c,l),this.image=u,this.isCubeDepthTexture=!0,this.isCubeTexture=!0}get images(){return this.image}set images(e){this.image=e}},ia=class extends jn{constructor(e=null){super(),this.sourceTexture=e,this.isExternalTexture=!0}copy(e){return super.copy(e),this.sourceTexture=e.sourceTexture,this}},Qr=class i extends An{constructor(e=1,t=1,n=1,s=1,r=1,o=1){super(),this.type="BoxGeometry",this.parameters={width:e,height:t,depth:n,widthSegments:s,heightSegments:r,depthSegments:o};let a=this;s=Math.floor(s),r=Math.floor(r),o=Math.floor(o);let c=[],l=[],d=[],u=[],h=0,m=0;g("z","y","x",-1,-1,n,t,e,o,r,0),g("z","y","x",1,-1,n,t,-e,o,r,1),g("x","z","y",1,1,e,n,t,s,o,2),g("x","z","y",1,-1,e,n,-t,s,o,3),g("x","y","z",1,-1,e,t,n,s,r,4),g("x","y","z",-1,-1,e,t,-n,s,r,5),this.setIndex(c),this.setAttribute("position",new Ot(l,3)),this.setAttribute("normal",new Ot(d,3)),this.setAttribute("uv",new Ot(u,2));function g(v,p,f,y,C,M,R,b,_,A,H){let O=M/_,T=R/A,F=M/2,B=R/2,D=b/2,V=_+1,Y=A+1,$=0,ce=0,P=new W;for(let I=0;I<Y;I++){let q=I*T-B;for(let ie=0;ie<V;ie++){let he=ie*O-F;P[v]=he*y,P[p]=q*C,P[f]=D,l.push(P.x,P.y,P.z),P[v]=0,P[p]=0,P[f]=b>0?1:-1,d.push(P.x,P.y,P.z),u.push(ie/_),u.push(1-I/A),$+=1}}for(let I=0;I<A;I++)for(let q=0;q<_;q++){let ie=h+q+V*I,he=h+q+V*(I+1),Q=h+(q+1)+V*(I+1),fe=h+(q+1)+V*I;c.push(ie,he,fe),c.push(he,Q,fe),ce+=6}a.addGroup(m,ce,H),m+=ce,h+=$}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new i(e.width,e.height,e.depth,e.widthSegments,e.heightSegments,e.depthSegments)}};var sa=class i extends An{constructor(e=1,t=1,n=1,s=1){super(),this.type="PlaneGeometry",this.parameters={width:e,height:t,widthSegments:n,heightSegments:s};let r=e/2,o=t/2,a=Math.floor(n),c=Math.floor(s),l=a+1,d=c+1,u=e/a,h=t/c,m=[],g=[],v=[],p=[];for(let f=0;f<d;f++){let y=f*h-o;for(let C=0;C<l;C++){let M=C*u-r;g.push(M,-y,0),v.push(0,0,1),p.push(C/a),p.push(1-f/c)}}for(let f=0;f<c;f++)for(let y=0;y<a;y++){let C=y+l*f,M=y+l*(f+1),R=y+1+l*(f+1),b=y+1+l*f;m.push(C,M,b),m.push(M,R,b)}this.setIndex(m),this.setAttribute("position",new Ot(g,3)),this.setAttribute("normal",new Ot(v,3)),this.setAttribute("uv",new Ot(p,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new i(e.width,e.height,e.widthSegments,e.heightSegments)}};var ra=class i extends An{constructor(e=1,t=32,n=16,s=0,r=Math.PI*2,o=0,a=Math.PI){super(),this.type="SphereGeometry",this.parameters={radius:e,widthSegments:t,heightSegments:n,phiStart:s,phiLength:r,thetaStart:o,thetaLength:a},t=Math.max(3,Math.floor(t)),n=Math.max(2,Math.floor(n));let c=Math.min(o+a,Math.PI),l=0,d=[],u=new W,h=new W,m=[],g=[],v=[],p=[];for(let f=0;f<=n;f++){let y=[],C=f/n,M=o+C*a,R=e*Math.cos(M),b=Math.sqrt(e*e-R*R),_=0;f===0&&o===0?_=.5/t:f===n&&c===Math.PI&&(_=-.5/t);for(let A=0;A<=t;A++){let H=A/t,O=s+H*r;u.x=-b*Math.cos(O),u.y=R,u.z=b*Math.sin(O),g.push(u.x,u.y,u.z),h.copy(u).normalize(),v.push(h.x,h.y,h.z),p.push(H+_,1-C),y.push(l++)}d.push(y)}for(let f=0;f<n;f++)for(let y=0;y<t;y++){let C=d[f][y+1],M=d[f][y],R=d[f+1][y],b=d[f+1][y+1];(f!==0||o>0)&&m.push(C,M,b),(f!==n-1||c<Math.PI)&&m.push(M,R,b)}this.setIndex(m),this.setAttribute("position",new Ot(g,3)),this.setAttribute("normal",new Ot(v,3)),this.setAttribute("uv",new Ot(p,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new i(e.radius,e.widthSegments,e.heightSegments,e.phiStart,e.phiLength,e.thetaStart,e.thetaLength)}};var oa=class i extends An{constructor(e=1,t=.4,n=12,s=48,r=Math.PI*2,o=0,a=Math.PI*2){super(),this.type="TorusGeometry",this.parameters={radius:e,tube:t,radialSegments:n,tubularSegments:s,arc:r,thetaStart:o,thetaLength:a},n=Math.floor(n),s=Math.floor(s);let c=[],l=[],d=[],u=[],h=new W,m=new W,g=new W;for(let v=0;v<=n;v++){let p=o+v/n*a;for(let f=0;f<=s;f++){let y=f/s*r;m.x=(e+t*Math.cos(p))*Math.cos(y),m.y=(e+t*Math.cos(p))*Math.sin(y),m.z=t*Math.sin(p),l.push(m.x,m.y,m.z),h.x=e*Math.cos(y),h.y=e*Math.sin(y),g.subVectors(m,h).normalize(),d.push(g.x,g.y,g.z),u.push(f/s),u.push(v/n)}}for(let v=1;v<=n;v++)for(let p=1;p<=s;p++){let f=(s+1)*v+p-1,y=(s+1)*(v-1)+p-1,C=(s+1)*(v-1)+p,M=(s+1)*v+p;c.push(f,y,M),c.push(y,C,M)}this.setIndex(c),this.setAttribute("position",new Ot(l,3)),this.setAttribute("normal",new Ot(d,3)),this.setAttribute("uv",new Ot(u,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new i(e.radius,e.tube,e.radialSegments,e.tubularSegments,e.arc,e.thetaStart,e.thetaLength)}};var aa=class extends An{constructor(e=null){if(super(),this.type="WireframeGeometry",this.parameters={geometry:e},e!==null){let t=[],n=new Set,s=new W,r=new W;if(e.index!==null){let o=e.attributes.position,a=e.index,c=e.groups;c.length===0&&(c=[{start:0,count:a.count,materialIndex:0}]);for(let l=0,d=c.length;l<d;++l){let u=c[l],h=u.start,m=u.count;for(let g=h,v=h+m;g<v;g+=3)for(let p=0;p<3;p++){let f=a.getX(g+p),y=a.getX(g+(p+1)%3);s.fromBufferAttribute(o,f),r.fromBufferAttribute(o,y),Vf(s,r,n)===!0&&(t.push(s.x,s.y,s.z),t.push(r.x,r.y,r.z))}}}else{let o=e.attributes.position;for(let a=0,c=o.count/3;a<c;a++)for(let l=0;l<3;l++){let d=3*a+l,u=3*a+(l+1)%3;s.fromBufferAttribute(o,d),r.fromBufferAttribute(o,u),Vf(s,r,n)===!0&&(t.push(s.x,s.y,s.z),t.push(r.x,r.y,r.z))}}this.setAttribute("position",new Ot(t,3))}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}};function Vf(i,e,t){let n=`${i.x},${i.y},${i.z}-${e.x},${e.y},${e.z}`,s=`${e.x},${e.y},${e.z}-${i.x},${i.y},${i.z}`;return t.has(n)===!0||t.has(s)===!0?!1:(t.add(n),t.add(s),!0)}function hr(i){let e={};for(let t in i){e[t]={};for(let n in i[t]){let s=i[t][n];if(Hf(s))s.isRenderTargetTexture?(Ye("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),e[t][n]=null):e[t][n]=s.clone();else if(Array.isArray(s))if(Hf(s[0])){let r=[];for(let o=0,a=s.length;o<a;o++)r[o]=s[o].clone();e[t][n]=r}else e[t][n]=s.slice();else e[t][n]=s}}return e}function Bn(i){let e={};for(let t=0;t<i.length;t++){let n=hr(i[t]);for(let s in n)e[s]=n[s]}return e}function Hf(i){return i&&(i.isColor||i.isMatrix3||i.isMatrix4||i.isVector2||i.isVector3||i.isVector4||i.isTexture||i.isQuaternion)}function y_(i){let e=[];for(let t=0;t<i.length;t++)e.push(i[t].clone());return e}function Bu(i){let e=i.getRenderTarget();return e===null?i.outputColorSpace:e.isXRRenderTarget===!0?e.texture.colorSpace:_t.workingColorSpace}var Ra={clone:hr,merge:Bn},b_=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,S_=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`,yi=class extends _s{constructor(e){super(),this.isShaderMaterial=!0,this.type="ShaderMaterial",this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=b_,this.fragmentShader=S_,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,e!==void 0&&this.setValues(e)}copy(e){return super.copy(e),this.fragmentShader=e.fragmentShader,this.vertexShader=e.vertexShader,this.uniforms=hr(e.uniforms),this.uniformsGroups=y_(e.uniformsGroups),this.defines=Object.assign({},e.defines),this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.fog=e.fog,this.lights=e.lights,this.clipping=e.clipping,this.extensions=Object.assign({},e.extensions),this.glslVersion=e.glslVersion,this.defaultAttributeValues=Object.assign({},e.defaultAttributeValues),this.index0AttributeName=e.index0AttributeName,this.uniformsNeedUpdate=e.uniformsNeedUpdate,this}toJSON(e){let t=super.toJSON(e);t.glslVersion=this.glslVersion,t.uniforms={};for(let s in this.uniforms){let o=this.uniforms[s].value;o&&o.isTexture?t.uniforms[s]={type:"t",value:o.toJSON(e).uuid}:o&&o.isColor?t.uniforms[s]={type:"c",value:o.getHex()}:o&&o.isVector2?t.uniforms[s]={type:"v2",value:o.toArray()}:o&&o.isVector3?t.uniforms[s]={type:"v3",value:o.toArray()}:o&&o.isVector4?t.uniforms[s]={type:"v4",value:o.toArray()}:o&&o.isMatrix3?t.uniforms[s]={type:"m3",value:o.toArray()}:o&&o.isMatrix4?t.uniforms[s]={type:"m4",value:o.toArray()}:t.uniforms[s]={value:o}}Object.keys(this.defines).length>0&&(t.defines=this.defines),t.vertexShader=this.vertexShader,t.fragmentShader=this.fragmentShader,t.lights=this.lights,t.clipping=this.clipping;let n={};for(let s in this.extensions)this.extensions[s]===!0&&(n[s]=!0);return Object.keys(n).length>0&&(t.extensions=n),t}fromJSON(e,t){if(super.fromJSON(e,t),e.uniforms!==void 0)for(let n in e.uniforms){let s=e.uniforms[n];switch(this.uniforms[n]={},s.type){case"t":this.uniforms[n].value=t[s.value]||null;break;case"c":this.uniforms[n].value=new ct().setHex(s.value);break;case"v2":this.uniforms[n].value=new je().fromArray(s.value);break;case"v3":this.uniforms[n].value=new W().fromArray(s.value);break;case"v4":this.uniforms[n].value=new Ct().fromArray(s.value);break;case"m3":this.uniforms[n].value=new st().fromArray(s.value);break;case"m4":this.uniforms[n].value=new kt().fromArray(s.value);break;default:this.uniforms[n].value=s.value}}if(e.defines!==void 0&&(this.defines=e.defines),e.vertexShader!==void 0&&(this.vertexShader=e.vertexShader),e.fragmentShader!==void 0&&(this.fragmentShader=e.fragmentShader),e.glslVersion!==void 0&&(this.glslVersion=e.glslVersion),e.extensions!==void 0)for(let n in e.extensions)this.extensions[n]=e.extensions[n];return e.lights!==void 0&&(this.lights=e.lights),e.clipping!==void 0&&(this.clipping=e.clipping),this}},Fl=class extends yi{constructor(e){super(e),this.isRawShaderMaterial=!0,this.type="RawShaderMaterial"}},rr=class extends _s{constructor(e){super(),this.isMeshStandardMaterial=!0,this.type="MeshStandardMaterial",this.defines={STANDARD:""},this.color=new ct(16777215),this.roughness=1,this.metalness=0,this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.emissive=new ct(0),this.emissiveIntensity=1,this.emissiveMap=null,this.bumpMap=null,this.bumpScale=1,this.normalMap=null,this.normalMapType=Oc,this.normalScale=new je(1,1),this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.roughnessMap=null,this.metalnessMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new gs,this.envMapIntensity=1,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.flatShading=!1,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.defines={STANDARD:""},this.color.copy(e.color),this.roughness=e.roughness,this.metalness=e.metalness,this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.emissive.copy(e.emissive),this.emissiveMap=e.emissiveMap,this.emissiveIntensity=e.emissiveIntensity,this.bumpMap=e.bumpMap,this.bumpScale=e.bumpScale,this.normalMap=e.normalMap,this.normalMapType=e.normalMapType,this.normalScale.copy(e.normalScale),this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.roughnessMap=e.roughnessMap,this.metalnessMap=e.metalnessMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.envMapIntensity=e.envMapIntensity,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.flatShading=e.flatShading,this.fog=e.fog,this}};var Ol=class extends _s{constructor(e){super(),this.isMeshDepthMaterial=!0,this.type="MeshDepthMaterial",this.depthPacking=yp,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(e)}copy(e){return super.copy(e),this.depthPacking=e.depthPacking,this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this}},Bl=class extends _s{constructor(e){super(),this.isMeshDistanceMaterial=!0,this.type="MeshDistanceMaterial",this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(e)}copy(e){return super.copy(e),this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this}};function zr(i,e){return!i||i.constructor===e?i:typeof e.BYTES_PER_ELEMENT=="number"?new e(i):Array.prototype.slice.call(i)}function dl(i){return i!==void 0&&i.inTangents!==void 0&&i.outTangents!==void 0}var Bs=class{constructor(e,t,n,s){this.parameterPositions=e,this._cachedIndex=0,this.resultBuffer=s!==void 0?s:new t.constructor(n),this.sampleValues=t,this.valueSize=n,this.settings=null,this.DefaultSettings_={}}evaluate(e){let t=this.parameterPositions,n=this._cachedIndex,s=t[n],r=t[n-1];n:{e:{let o;t:{i:if(!(e<s)){for(let a=n+2;;){if(s===void 0){if(e<r)break i;return n=t.length,this._cachedIndex=n,this.copySampleValue_(n-1)}if(n===a)break;if(r=s,s=t[++n],e<s)break e}o=t.length;break t}if(!(e>=r)){let a=t[1];e<a&&(n=2,r=a);for(let c=n-2;;){if(r===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(n===c)break;if(s=r,r=t[--n-1],e>=r)break e}o=n,n=0;break t}break n}for(;n<o;){let a=n+o>>>1;e<t[a]?o=a:n=a+1}if(s=t[n],r=t[n-1],r===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(s===void 0)return n=t.length,this._cachedIndex=n,this.copySampleValue_(n-1)}this._cachedIndex=n,this.intervalChanged_(n,r,s)}return this.interpolate_(n,r,e,s)}getSettings_(){return this.settings||this.DefaultSettings_}copySampleValue_(e){let t=this.resultBuffer,n=this.sampleValues,s=this.valueSize,r=e*s;for(let o=0;o!==s;++o)t[o]=n[r+o];return t}interpolate_(){throw new Error("THREE.Interpolant: Call to abstract method.")}intervalChanged_(){}},kl=class extends Bs{constructor(e,t,n,s){super(e,t,n,s),this._weightPrev=-0,this._offsetPrev=-0,this._weightNext=-0,this._offsetNext=-0,this.DefaultSettings_={endingStart:tu,endingEnd:tu}}intervalChanged_(e,t,n){let s=this.parameterPositions,r=e-2,o=e+1,a=s[r],c=s[o];if(a===void 0)switch(this.getSettings_().endingStart){case nu:r=e,a=2*t-n;break;case iu:r=s.length-2,a=t+s[r]-s[r+1];break;default:r=e,a=n}if(c===void 0)switch(this.getSettings_().endingEnd){case nu:o=e,c=2*n-t;break;case iu:o=1,c=n+s[1]-s[0];break;default:o=e-1,c=t}let l=(n-t)*.5,d=this.valueSize;this._weightPrev=l/(t-a),this._weightNext=l/(c-n),this._offsetPrev=r*d,this._offsetNext=o*d}interpolate_(e,t,n,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,c=e*a,l=c-a,d=this._offsetPrev,u=this._offsetNext,h=this._weightPrev,m=this._weightNext,g=(n-t)/(s-t),v=g*g,p=v*g,f=-h*p+2*h*v-h*g,y=(1+h)*p+(-1.5-2*h)*v+(-.5+h)*g+1,C=(-1-m)*p+(1.5+m)*v+.5*g,M=m*p-m*v;for(let R=0;R!==a;++R)r[R]=f*o[d+R]+y*o[l+R]+C*o[c+R]+M*o[u+R];return r}},zl=class extends Bs{constructor(e,t,n,s){super(e,t,n,s)}interpolate_(e,t,n,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,c=e*a,l=c-a,d=(n-t)/(s-t),u=1-d;for(let h=0;h!==a;++h)r[h]=o[l+h]*u+o[c+h]*d;return r}},Vl=class extends Bs{constructor(e,t,n,s){super(e,t,n,s)}interpolate_(e){return this.copySampleValue_(e-1)}},Hl=class extends Bs{interpolate_(e,t,n,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,c=e*a,l=c-a,d=this.inTangents,u=this.outTangents;if(!d||!u){let g=(n-t)/(s-t),v=1-g;for(let p=0;p!==a;++p)r[p]=o[l+p]*v+o[c+p]*g;return r}let h=a*2,m=e-1;for(let g=0;g!==a;++g){let v=o[l+g],p=o[c+g],f=m*h+g*2,y=u[f],C=u[f+1],M=e*h+g*2,R=d[M],b=d[M+1],_=w_(n,t,y,R,s);r[g]=Dp(_,v,C,b,p)}return r}};function Dp(i,e,t,n,s){let r=1-i;return r*r*r*e+3*r*r*i*t+3*r*i*i*n+i*i*i*s}function M_(i,e,t,n,s){let r=1-i;return 3*r*r*(t-e)+6*r*i*(n-t)+3*i*i*(s-n)}function w_(i,e,t,n,s){let r=(i-e)/(s-e);for(let o=0;o<8;o++){let a=Dp(r,e,t,n,s)-i;if(Math.abs(a)<1e-10)break;let c=M_(r,e,t,n,s);if(Math.abs(c)<1e-10)break;r=Math.max(0,Math.min(1,r-a/c))}return r}var ui=class{constructor(e,t,n,s){if(e===void 0)throw new Error("THREE.KeyframeTrack: track name is undefined");if(t===void 0||t.length===0)throw new Error("THREE.KeyframeTrack: no keyframes in track named "+e);this.name=e,this.times=zr(t,this.TimeBufferType),this.values=zr(n,this.ValueBufferType),this.setInterpolation(s||this.DefaultInterpolation)}static toJSON(e){let t=e.constructor,n;if(t.toJSON!==this.toJSON)n=t.toJSON(e);else{n={name:e.name,times:zr(e.times,Array),values:zr(e.values,Array)};let s=e.getInterpolation();s!==e.DefaultInterpolation&&(n.interpolation=s),dl(e.settings)&&(n.settings={inTangents:zr(e.settings.inTangents,Array),outTangents:zr(e.settings.outTangents,Array)})}return n.type=e.ValueTypeName,n}InterpolantFactoryMethodDiscrete(e){return new Vl(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodLinear(e){return new zl(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodSmooth(e){return new kl(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodBezier(e){let t=new Hl(this.times,this.values,this.getValueSize(),e);return this.settings&&(t.inTangents=this.settings.inTangents,t.outTangents=this.settings.outTangents),t}setInterpolation(e){let t;switch(e){case Wo:t=this.InterpolantFactoryMethodDiscrete;break;case Al:t=this.InterpolantFactoryMethodLinear;break;case gl:t=this.InterpolantFactoryMethodSmooth;break;case eu:t=this.InterpolantFactoryMethodBezier;break}if(t===void 0){let n="unsupported interpolation for "+this.ValueTypeName+" keyframe track named "+this.name;if(this.createInterpolant===void 0)if(e!==this.DefaultInterpolation)this.setInterpolation(this.DefaultInterpolation);else throw new Error(n);return Ye("KeyframeTrack:",n),this}return this.createInterpolant=t,this}getInterpolation(){switch(this.createInterpolant){case this.InterpolantFactoryMethodDiscrete:return Wo;case this.InterpolantFactoryMethodLinear:return Al;case this.InterpolantFactoryMethodSmooth:return gl;case this.InterpolantFactoryMethodBezier:return eu}}getValueSize(){return this.values.length/this.times.length}shift(e){if(e!==0){let t=this.times;for(let n=0,s=t.length;n!==s;++n)t[n]+=e;dl(this.settings)&&(Gf(this.settings.inTangents,e),Gf(this.settings.outTangents,e))}return this}scale(e){if(e!==1){let t=this.times;for(let n=0,s=t.length;n!==s;++n)t[n]*=e;dl(this.settings)&&(Wf(this.settings.inTangents,e),Wf(this.settings.outTangents,e))}return this}trim(e,t){let n=this.times,s=n.length,r=0,o=s-1;for(;r!==s&&n[r]<e;)++r;for(;o!==-1&&n[o]>t;)--o;if(++o,r!==0||o!==s){r>=o&&(o=Math.max(o,1),r=o-1);let a=this.getValueSize();this.times=n.slice(r,o),this.values=this.values.slice(r*a,o*a)}return this}validate(){let e=!0,t=this.getValueSize();t-Math.floor(t)!==0&&(it("KeyframeTrack: Invalid value size in track.",this),e=!1);let n=this.times,s=this.values,r=n.length;r===0&&(it("KeyframeTrack: Track is empty.",this),e=!1);let o=null;for(let a=0;a!==r;a++){let c=n[a];if(typeof c=="number"&&isNaN(c)){it("KeyframeTrack: Time is not a valid number.",this,a,c),e=!1;break}if(o!==null&&o>c){it("KeyframeTrack: Out of order keys.",this,a,c,o),e=!1;break}o=c}if(s!==void 0&&z0(s))for(let a=0,c=s.length;a!==c;++a){let l=s[a];if(isNaN(l)){it("KeyframeTrack: Value is not a valid number.",this,a,l),e=!1;break}}return e}optimize(){let e=this.times.slice(),t=this.values.slice(),n=this.getValueSize(),s=this.getInterpolation()===gl,r=e.length-1,o=1;for(let a=1;a<r;++a){let c=!1,l=e[a],d=e[a+1];if(l!==d&&(a!==1||l!==e[0]))if(s)c=!0;else{let u=a*n,h=u-n,m=u+n;for(let g=0;g!==n;++g){let v=t[u+g];if(v!==t[h+g]||v!==t[m+g]){c=!0;break}}}if(c){if(a!==o){e[o]=e[a];let u=a*n,h=o*n;for(let m=0;m!==n;++m)t[h+m]=t[u+m]}++o}}if(r>0){e[o]=e[r];for(let a=r*n,c=o*n,l=0;l!==n;++l)t[c+l]=t[a+l];++o}return o!==e.length?(this.times=e.slice(0,o),this.values=t.slice(0,o*n)):(this.times=e,this.values=t),this}clone(){let e=this.times.slice(),t=this.values.slice(),n=this.constructor,s=new n(this.name,e,t);return s.createInterpolant=this.createInterpolant,dl(this.settings)&&(s.settings={inTangents:this.settings.inTangents.slice(),outTangents:this.settings.outTangents.slice()}),s}};function Gf(i,e){for(let t=0,n=i.length;t!==n;t+=2)i[t]+=e}function Wf(i,e){for(let t=0,n=i.length;t!==n;t+=2)i[t]*=e}ui.prototype.ValueTypeName="";ui.prototype.TimeBufferType=Float32Array;ui.prototype.ValueBufferType=Float32Array;ui.prototype.DefaultInterpolation=Al;var ks=class extends ui{constructor(e,t,n){super(e,t,n)}};ks.prototype.ValueTypeName="bool";ks.prototype.ValueBufferType=Array;ks.prototype.DefaultInterpolation=Wo;ks.prototype.InterpolantFactoryMethodLinear=void 0;ks.prototype.InterpolantFactoryMethodSmooth=void 0;var Gl=class extends ui{constructor(e,t,n,s){super(e,t,n,s)}};Gl.prototype.ValueTypeName="color";var Wl=class extends ui{constructor(e,t,n,s){super(e,t,n,s)}};Wl.prototype.ValueTypeName="number";var $l=class extends Bs{constructor(e,t,n,s){super(e,t,n,s)}interpolate_(e,t,n,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,c=(n-t)/(s-t),l=e*a;for(let d=l+a;l!==d;l+=4)ci.slerpFlat(r,0,o,l-a,o,l,c);return r}},la=class extends ui{constructor(e,t,n,s){super(e,t,n,s)}InterpolantFactoryMethodLinear(e){return new $l(this.times,this.values,this.getValueSize(),e)}};la.prototype.ValueTypeName="quaternion";la.prototype.InterpolantFactoryMethodSmooth=void 0;var zs=class extends ui{constructor(e,t,n){super(e,t,n)}};zs.prototype.ValueTypeName="string";zs.prototype.ValueBufferType=Array;zs.prototype.DefaultInterpolation=Wo;zs.prototype.InterpolantFactoryMethodLinear=void 0;zs.prototype.InterpolantFactoryMethodSmooth=void 0;var Xl=class extends ui{constructor(e,t,n,s){super(e,t,n,s)}};Xl.prototype.ValueTypeName="vector";var ql=class{constructor(e,t,n){let s=this,r=!1,o=0,a=0,c,l=[];this.onStart=void 0,this.onLoad=e,this.onProgress=t,this.onError=n,this._abortController=null,this.itemStart=function(d){a++,r===!1&&s.onStart!==void 0&&s.onStart(d,o,a),r=!0},this.itemEnd=function(d){o++,s.onProgress!==void 0&&s.onProgress(d,o,a),o===a&&(r=!1,s.onLoad!==void 0&&s.onLoad())},this.itemError=function(d){s.onError!==void 0&&s.onError(d)},this.resolveURL=function(d){return d=d.normalize("NFC"),c?c(d):d},this.setURLModifier=function(d){return c=d,this},this.addHandler=function(d,u){return l.push(d,u),this},this.removeHandler=function(d){let u=l.indexOf(d);return u!==-1&&l.splice(u,2),this},this.getHandler=function(d){for(let u=0,h=l.length;u<h;u+=2){let m=l[u],g=l[u+1];if(m.global&&(m.lastIndex=0),m.test(d))return g}return null},this.abort=function(){return this.abortController.abort(),this._abortController=null,this}}get abortController(){return this._abortController||(this._abortController=new AbortController),this._abortController}},Np=new ql,Yl=class{constructor(e){this.manager=e!==void 0?e:Np,this.crossOrigin="anonymous",this.withCredentials=!1,this.path="",this.resourcePath="",this.requestHeader={},this.priority="auto",this.cache="default",typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}load(){}loadAsync(e,t){let n=this;return new Promise(function(s,r){n.load(e,s,t,r)})}parse(){}setCrossOrigin(e){return this.crossOrigin=e,this}setWithCredentials(e){return this.withCredentials=e,this}setPath(e){return this.path=e,this}setResourcePath(e){return this.resourcePath=e,this}setRequestHeader(e){return this.requestHeader=e,this}setPriority(e){return this.priority=e,this}setCache(e){return this.cache=e,this}abort(){return this}};Yl.DEFAULT_MATERIAL_NAME="__DEFAULT";var ca=class extends Cn{static registerNode(e){this.prototype._lightNode=e}constructor(e,t=1){super(),this.isLight=!0,this.type="Light",this.color=new ct(e),this.intensity=t}copy(e,t){return super.copy(e,t),this.color.copy(e.color),this.intensity=e.intensity,this}toJSON(e){let t=super.toJSON(e);return t.object.color=this.color.getHex(),t.object.intensity=this.intensity,t}},ha=class extends ca{constructor(e,t,n){super(e,n),this.isHemisphereLight=!0,this.type="HemisphereLight",this.position.copy(Cn.DEFAULT_UP),this.updateMatrix(),this.groundColor=new ct(t)}copy(e,t){return super.copy(e,t),this.groundColor.copy(e.groundColor),this}toJSON(e){let t=super.toJSON(e);return t.object.groundColor=this.groundColor.getHex(),t}},jh=new kt,$f=new W,Xf=new W,Zl=class{constructor(e){this.camera=e,this.intensity=1,this.bias=0,this.biasNode=null,this.normalBias=0,this.radius=1,this.blurSamples=8,this.mapSize=new je(512,512),this.mapType=Qn,this.map=null,this.mapPass=null,this.matrix=new kt,this.autoUpdate=!0,this.needsUpdate=!1,this._frustum=new Os,this._frameExtents=new je(1,1),this._viewportCount=1,this._viewports=[new Ct(0,0,1,1)]}getViewportCount(){return this._viewportCount}getCamera(){return this.camera}getFrustum(){return this._frustum}updateMatrices(e){let t=this.camera;$f.setFromMatrixPosition(e.matrixWorld),t.position.copy($f),Xf.setFromMatrixPosition(e.target.matrixWorld),t.lookAt(Xf),t.updateMatrixWorld(),this._updateMatrix(t,this.matrix,this._frustum)}_updateMatrix(e,t,n,s){jh.multiplyMatrices(e.projectionMatrix,e.matrixWorldInverse),n.setFromProjectionMatrix(jh,e.coordinateSystem,e.reversedDepth);let r=this._frameExtents,o=s?s.z/r.x:1,a=s?s.w/r.y:1,c=s?s.x/r.x:0,l=s?s.y/r.y:0;e.coordinateSystem===qr||e.reversedDepth?t.set(.5*o,0,0,.5*o+c,0,.5*a,0,.5*a+l,0,0,1,0,0,0,0,1):t.set(.5*o,0,0,.5*o+c,0,.5*a,0,.5*a+l,0,0,.5,.5,0,0,0,1),t.multiply(jh)}getViewport(e){return this._viewports[e]}getFrameExtents(){return this._frameExtents}dispose(){this.map&&this.map.dispose(),this.mapPass&&this.mapPass.dispose()}copy(e){return this.camera=e.camera.clone(),this.intensity=e.intensity,this.bias=e.bias,this.radius=e.radius,this.autoUpdate=e.autoUpdate,this.needsUpdate=e.needsUpdate,this.normalBias=e.normalBias,this.blurSamples=e.blurSamples,this.mapSize.copy(e.mapSize),this.mapType=e.mapType,this.biasNode=e.biasNode,this}clone(){return new this.constructor().copy(this)}toJSON(){let e={};return e.intensity=this.intensity,e.bias=this.bias,e.normalBias=this.normalBias,e.radius=this.radius,e.blurSamples=this.blurSamples,e.mapSize=this.mapSize.toArray(),e.mapType=this.mapType,e.camera=this.camera.toJSON(!1).object,delete e.camera.matrix,e}},fl=new W,pl=new ci,Xi=new W,ua=class extends Cn{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new kt,this.projectionMatrix=new kt,this.projectionMatrixInverse=new kt,this.coordinateSystem=vi,this._reversedDepth=!1}get reversedDepth(){return this._reversedDepth}copy(e,t){return super.copy(e,t),this.matrixWorldInverse.copy(e.matrixWorldInverse),this.projectionMatrix.copy(e.projectionMatrix),this.projectionMatrixInverse.copy(e.projectionMatrixInverse),this.coordinateSystem=e.coordinateSystem,this}getWorldDirection(e){return super.getWorldDirection(e).negate()}updateMatrixWorld(e){super.updateMatrixWorld(e),this.matrixWorld.decompose(fl,pl,Xi),Xi.x===1&&Xi.y===1&&Xi.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(fl,pl,Xi.set(1,1,1)).invert()}updateWorldMatrix(e,t,n=!1){super.updateWorldMatrix(e,t,n),this.matrixWorld.decompose(fl,pl,Xi),Xi.x===1&&Xi.y===1&&Xi.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(fl,pl,Xi.set(1,1,1)).invert()}clone(){return new this.constructor().copy(this)}},Us=new W,qf=new je,Yf=new je,$n=class extends ua{constructor(e=50,t=1,n=.1,s=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=e,this.zoom=1,this.near=n,this.far=s,this.focus=10,this.aspect=t,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.fov=e.fov,this.zoom=e.zoom,this.near=e.near,this.far=e.far,this.focus=e.focus,this.aspect=e.aspect,this.view=e.view===null?null:Object.assign({},e.view),this.filmGauge=e.filmGauge,this.filmOffset=e.filmOffset,this}setFocalLength(e){let t=.5*this.getFilmHeight()/e;this.fov=Zr*2*Math.atan(t),this.updateProjectionMatrix()}getFocalLength(){let e=Math.tan(Ho*.5*this.fov);return .5*this.getFilmHeight()/e}getEffectiveFOV(){return Zr*2*Math.atan(Math.tan(Ho*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(e,t,n){Us.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),t.set(Us.x,Us.y).multiplyScalar(-e/Us.z),Us.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),n.set(Us.x,Us.y).multiplyScalar(-e/Us.z)}getViewSize(e,t){return this.getViewBounds(e,qf,Yf),t.subVectors(Yf,qf)}setViewOffset(e,t,n,s,r,o){this.aspect=e/t,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=n,this.view.offsetY=s,this.view.width=r,this.view.height=o,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let e=this.near,t=e*Math.tan(Ho*.5*this.fov)/this.zoom,n=2*t,s=this.aspect*n,r=-.5*s,o=this.view;if(this.view!==null&&this.view.enabled){let c=o.fullWidth,l=o.fullHeight;r+=o.offsetX*s/c,t-=o.offsetY*n/l,s*=o.width/c,n*=o.height/l}let a=this.filmOffset;a!==0&&(r+=e*a/this.getFilmWidth()),this.projectionMatrix.makePerspective(r,r+s,t,t-n,e,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){let t=super.toJSON(e);return t.object.fov=this.fov,t.object.zoom=this.zoom,t.object.near=this.near,t.object.far=this.far,t.object.focus=this.focus,t.object.aspect=this.aspect,this.view!==null&&(t.object.view=Object.assign({},this.view)),t.object.filmGauge=this.filmGauge,t.object.filmOffset=this.filmOffset,t}};var da=class extends ua{constructor(e=-1,t=1,n=1,s=-1,r=.1,o=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=e,this.right=t,this.top=n,this.bottom=s,this.near=r,this.far=o,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.left=e.left,this.right=e.right,this.top=e.top,this.bottom=e.bottom,this.near=e.near,this.far=e.far,this.zoom=e.zoom,this.view=e.view===null?null:Object.assign({},e.view),this}setViewOffset(e,t,n,s,r,o){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=n,this.view.offsetY=s,this.view.width=r,this.view.height=o,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let e=(this.right-this.left)/(2*this.zoom),t=(this.top-this.bottom)/(2*this.zoom),n=(this.right+this.left)/2,s=(this.top+this.bottom)/2,r=n-e,o=n+e,a=s+t,c=s-t;if(this.view!==null&&this.view.enabled){let l=(this.right-this.left)/this.view.fullWidth/this.zoom,d=(this.top-this.bottom)/this.view.fullHeight/this.zoom;r+=l*this.view.offsetX,o=r+l*this.view.width,a-=d*this.view.offsetY,c=a-d*this.view.height}this.projectionMatrix.makeOrthographic(r,o,a,c,this.near,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){let t=super.toJSON(e);return t.object.zoom=this.zoom,t.object.left=this.left,t.object.right=this.right,t.object.top=this.top,t.object.bottom=this.bottom,t.object.near=this.near,t.object.far=this.far,this.view!==null&&(t.object.view=Object.assign({},this.view)),t}},su=class extends Zl{constructor(){super(new da(-5,5,5,-5,.5,500)),this.isDirectionalLightShadow=!0}},fa=class extends ca{constructor(e,t){super(e,t),this.isDirectionalLight=!0,this.type="DirectionalLight",this.position.copy(Cn.DEFAULT_UP),this.updateMatrix(),this.target=new Cn,this.shadow=new su}dispose(){super.dispose(),this.shadow.dispose()}copy(e){return super.copy(e),this.target=e.target.clone(),this.shadow=e.shadow.clone(),this}toJSON(e){let t=super.toJSON(e);return t.object.shadow=this.shadow.toJSON(),t.object.target=this.target.uuid,t}};var pa=class extends An{constructor(){super(),this.isInstancedBufferGeometry=!0,this.type="InstancedBufferGeometry",this.instanceCount=1/0}copy(e){return super.copy(e),this.instanceCount=e.instanceCount,this}toJSON(){let e=super.toJSON();return e.instanceCount=this.instanceCount,e.isInstancedBufferGeometry=!0,e}};var Vr=-90,Hr=1,eo=class extends Cn{constructor(e,t,n){super(),this.type="CubeCamera",this.renderTarget=n,this.coordinateSystem=null,this.activeMipmapLevel=0;let s=new $n(Vr,Hr,e,t);s.layers=this.layers,this.add(s);let r=new $n(Vr,Hr,e,t);r.layers=this.layers,this.add(r);let o=new $n(Vr,Hr,e,t);o.layers=this.layers,this.add(o);let a=new $n(Vr,Hr,e,t);a.layers=this.layers,this.add(a);let c=new $n(Vr,Hr,e,t);c.layers=this.layers,this.add(c);let l=new $n(Vr,Hr,e,t);l.layers=this.layers,this.add(l)}updateCoordinateSystem(){let e=this.coordinateSystem,t=this.children.concat(),[n,s,r,o,a,c]=t;for(let l of t)this.remove(l);if(e===vi)n.up.set(0,1,0),n.lookAt(1,0,0),s.up.set(0,1,0),s.lookAt(-1,0,0),r.up.set(0,0,-1),r.lookAt(0,1,0),o.up.set(0,0,1),o.lookAt(0,-1,0),a.up.set(0,1,0),a.lookAt(0,0,1),c.up.set(0,1,0),c.lookAt(0,0,-1);else if(e===qr)n.up.set(0,-1,0),n.lookAt(-1,0,0),s.up.set(0,-1,0),s.lookAt(1,0,0),r.up.set(0,0,1),r.lookAt(0,1,0),o.up.set(0,0,-1),o.lookAt(0,-1,0),a.up.set(0,-1,0),a.lookAt(0,0,1),c.up.set(0,-1,0),c.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+e);for(let l of t)this.add(l),l.updateMatrixWorld()}update(e,t){this.parent===null&&this.updateMatrixWorld();let{renderTarget:n,activeMipmapLevel:s}=this;this.coordinateSystem!==e.coordinateSystem&&(this.coordinateSystem=e.coordinateSystem,this.updateCoordinateSystem());let[r,o,a,c,l,d]=this.children,u=e.getRenderTarget(),h=e.getActiveCubeFace(),m=e.getActiveMipmapLevel(),g=e.xr.enabled;e.xr.enabled=!1;let v=n.texture.mipmapsAutoUpdate;n.texture.mipmapsAutoUpdate=!1;let p=!1;e.isWebGLRenderer===!0?p=e.state.buffers.depth.getReversed():p=e.reversedDepthBuffer,e.setRenderTarget(n,0,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,r),e.setRenderTarget(n,1,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,o),e.setRenderTarget(n,2,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,a),e.setRenderTarget(n,3,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,c),e.setRenderTarget(n,4,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,l),n.texture.mipmapsAutoUpdate=v,e.setRenderTarget(n,5,s),p&&e.autoClear===!1&&e.clearDepth(),e.render(t,d),e.setRenderTarget(u,h,m),e.xr.enabled=g,n.texture.needsPMREMUpdate=!0}},Jl=class extends $n{constructor(e=[]){super(),this.isArrayCamera=!0,this.isMultiViewCamera=!1,this.cameras=e,this.perCameraFrustumCulled=!1}};var ku="\\[\\]\\.:\\/",E_=new RegExp("["+ku+"]","g"),zu="[^"+ku+"]",T_="[^"+ku.replace("\\.","")+"]",A_=/((?:WC+[\/:])*)/.source.replace("WC",zu),R_=/(WCOD+)?/.source.replace("WCOD",T_),C_=/(?:\.(WC+)(?:\[(.+)\])?)?/.source.replace("WC",zu),P_=/\.(WC+)(?:\[(.+)\])?/.source.replace("WC",zu),I_=new RegExp("^"+A_+R_+C_+P_+"$"),L_=["material","materials","bones","map"],ru=class{constructor(e,t,n){let s=n||Xt.parseTrackName(t);this._targetGroup=e,this._bindings=e.subscribe_(t,s)}getValue(e,t){this.bind();let n=this._targetGroup.nCachedObjects_,s=this._bindings[n];s!==void 0&&s.getValue(e,t)}setValue(e,t){let n=this._bindings;for(let s=this._targetGroup.nCachedObjects_,r=n.length;s!==r;++s)n[s].setValue(e,t)}bind(){let e=this._bindings;for(let t=this._targetGroup.nCachedObjects_,n=e.length;t!==n;++t)e[t].bind()}unbind(){let e=this._bindings;for(let t=this._targetGroup.nCachedObjects_,n=e.length;t!==n;++t)e[t].unbind()}},Xt=class i{constructor(e,t,n){this.path=t,this.parsedPath=n||i.parseTrackName(t),this.node=i.findNode(e,this.parsedPath.nodeName),this.rootNode=e,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}static create(e,t,n){return e&&e.isAnimationObjectGroup?new i.Composite(e,t,n):new i(e,t,n)}static sanitizeNodeName(e){return e.replace(/\s/g,"_").replace(E_,"")}static parseTrackName(e){let t=I_.exec(e);if(t===null)throw new Error("THREE.PropertyBinding: Cannot parse trackName: "+e);let n={nodeName:t[2],objectName:t[3],objectIndex:t[4],propertyName:t[5],propertyIndex:t[6]},s=n.nodeName&&n.nodeName.lastIndexOf(".");if(s!==void 0&&s!==-1){let r=n.nodeName.substring(s+1);L_.indexOf(r)!==-1&&(n.nodeName=n.nodeName.substring(0,s),n.objectName=r)}if(n.propertyName===null||n.propertyName.length===0)throw new Error("THREE.PropertyBinding: can not parse propertyName from trackName: "+e);return n}static findNode(e,t){if(t===void 0||t===""||t==="."||t===-1||t===e.name||t===e.uuid)return e;if(e.skeleton){let n=e.skeleton.getBoneByName(t);if(n!==void 0)return n}if(e.children){let n=function(r){for(let o=0;o<r.length;o++){let a=r[o];if(a.name===t||a.uuid===t)return a;let c=n(a.children);if(c)return c}return null},s=n(e.children);if(s)return s}return null}_getValue_unavailable(){}_setValue_unavailable(){}_getValue_direct(e,t){e[t]=this.targetObject[this.propertyName]}_getValue_array(e,t){let n=this.resolvedProperty;for(let s=0,r=n.length;s!==r;++s)e[t++]=n[s]}_getValue_arrayElement(e,t){e[t]=this.resolvedProperty[this.propertyIndex]}_getValue_toArray(e,t){this.resolvedProperty.toArray(e,t)}_setValue_direct(e,t){this.targetObject[this.propertyName]=e[t]}_setValue_direct_setNeedsUpdate(e,t){this.targetObject[this.propertyName]=e[t],this.targetObject.needsUpdate=!0}_setValue_direct_setMatrixWorldNeedsUpdate(e,t){this.targetObject[this.propertyName]=e[t],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_array(e,t){let n=this.resolvedProperty;for(let s=0,r=n.length;s!==r;++s)n[s]=e[t++]}_setValue_array_setNeedsUpdate(e,t){let n=this.resolvedProperty;for(let s=0,r=n.length;s!==r;++s)n[s]=e[t++];this.targetObject.needsUpdate=!0}_setValue_array_setMatrixWorldNeedsUpdate(e,t){let n=this.resolvedProperty;for(let s=0,r=n.length;s!==r;++s)n[s]=e[t++];this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_arrayElement(e,t){this.resolvedProperty[this.propertyIndex]=e[t]}_setValue_arrayElement_setNeedsUpdate(e,t){this.resolvedProperty[this.propertyIndex]=e[t],this.targetObject.needsUpdate=!0}_setValue_arrayElement_setMatrixWorldNeedsUpdate(e,t){this.resolvedProperty[this.propertyIndex]=e[t],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_fromArray(e,t){this.resolvedProperty.fromArray(e,t)}_setValue_fromArray_setNeedsUpdate(e,t){this.resolvedProperty.fromArray(e,t),this.targetObject.needsUpdate=!0}_setValue_fromArray_setMatrixWorldNeedsUpdate(e,t){this.resolvedProperty.fromArray(e,t),this.targetObject.matrixWorldNeedsUpdate=!0}_getValue_unbound(e,t){this.bind(),this.getValue(e,t)}_setValue_unbound(e,t){this.bind(),this.setValue(e,t)}bind(){let e=this.node,t=this.parsedPath,n=t.objectName,s=t.propertyName,r=t.propertyIndex;if(e||(e=i.findNode(this.rootNode,t.nodeName),this.node=e),this.getValue=this._getValue_unavailable,this.setValue=this._setValue_unavailable,!e){Ye("PropertyBinding: No target node found for track: "+this.path+".");return}if(n){let l=t.objectIndex;switch(n){case"materials":if(!e.material){it("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!e.material.materials){it("PropertyBinding: Can not bind to material.materials as node.material does not have a materials array.",this);return}e=e.material.materials;break;case"bones":if(!e.skeleton){it("PropertyBinding: Can not bind to bones as node does not have a skeleton.",this);return}e=e.skeleton.bones;for(let d=0;d<e.length;d++)if(e[d].name===l){l=d;break}break;case"map":if("map"in e){e=e.map;break}if(!e.material){it("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!e.material.map){it("PropertyBinding: Can not bind to material.map as node.material does not have a map.",this);return}e=e.material.map;break;default:if(e[n]===void 0){it("PropertyBinding: Can not bind to objectName of node undefined.",this);return}e=e[n]}if(l!==void 0){if(e[l]===void 0){it("PropertyBinding: Trying to bind to objectIndex of objectName, but is undefined.",this,e);return}e=e[l]}}let o=e[s];if(o===void 0){let l=t.nodeName;it("PropertyBinding: Trying to update property for track: "+l+"."+s+" but it wasn't found.",e);return}let a=this.Versioning.None;this.targetObject=e,e.isMaterial===!0?a=this.Versioning.NeedsUpdate:e.isObject3D===!0&&(a=this.Versioning.MatrixWorldNeedsUpdate);let c=this.BindingType.Direct;if(r!==void 0){if(s==="morphTargetInfluences"){if(!e.geometry){it("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.",this);return}if(!e.geometry.morphAttributes){it("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.morphAttributes.",this);return}e.morphTargetDictionary[r]!==void 0&&(r=e.morphTargetDictionary[r])}c=this.BindingType.ArrayElement,this.resolvedProperty=o,this.propertyIndex=r}else o.fromArray!==void 0&&o.toArray!==void 0?(c=this.BindingType.HasFromToArray,this.resolvedProperty=o):Array.isArray(o)?(c=this.BindingType.EntireArray,this.resolvedProperty=o):this.propertyName=s;this.getValue=this.GetterByBindingType[c],this.setValue=this.SetterByBindingTypeAndVersioning[c][a]}unbind(){this.node=null,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}};Xt.Composite=ru;Xt.prototype.BindingType={Direct:0,EntireArray:1,ArrayElement:2,HasFromToArray:3};Xt.prototype.Versioning={None:0,NeedsUpdate:1,MatrixWorldNeedsUpdate:2};Xt.prototype.GetterByBindingType=[Xt.prototype._getValue_direct,Xt.prototype._getValue_array,Xt.prototype._getValue_arrayElement,Xt.prototype._getValue_toArray];Xt.prototype.SetterByBindingTypeAndVersioning=[[Xt.prototype._setValue_direct,Xt.prototype._setValue_direct_setNeedsUpdate,Xt.prototype._setValue_direct_setMatrixWorldNeedsUpdate],[Xt.prototype._setValue_array,Xt.prototype._setValue_array_setNeedsUpdate,Xt.prototype._setValue_array_setMatrixWorldNeedsUpdate],[Xt.prototype._setValue_arrayElement,Xt.prototype._setValue_arrayElement_setNeedsUpdate,Xt.prototype._setValue_arrayElement_setMatrixWorldNeedsUpdate],[Xt.prototype._setValue_fromArray,Xt.prototype._setValue_fromArray_setNeedsUpdate,Xt.prototype._setValue_fromArray_setMatrixWorldNeedsUpdate]];var N1=new Float32Array(1);var Vs=class extends Il{constructor(e,t,n=1){super(e,t),this.isInstancedInterleavedBuffer=!0,this.meshPerAttribute=n}copy(e){return super.copy(e),this.meshPerAttribute=e.meshPerAttribute,this}clone(e){let t=super.clone(e);return t.meshPerAttribute=this.meshPerAttribute,t}toJSON(e){let t=super.toJSON(e);return t.isInstancedInterleavedBuffer=!0,t.meshPerAttribute=this.meshPerAttribute,t}};var to=class{constructor(e=1,t=0,n=0){this.radius=e,this.phi=t,this.theta=n}set(e,t,n){return this.radius=e,this.phi=t,this.theta=n,this}copy(e){return this.radius=e.radius,this.phi=e.phi,this.theta=e.theta,this}makeSafe(){return this.phi=lt(this.phi,1e-6,Math.PI-1e-6),this}setFromVector3(e){return this.setFromCartesianCoords(e.x,e.y,e.z)}setFromCartesianCoords(e,t,n){return this.radius=Math.sqrt(e*e+t*t+n*n),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(e,n),this.phi=Math.acos(lt(t/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}};var Xu=class Xu{constructor(e,t,n,s){this.elements=[1,0,0,1],e!==void 0&&this.set(e,t,n,s)}identity(){return this.set(1,0,0,1),this}fromArray(e,t=0){for(let n=0;n<4;n++)this.elements[n]=e[n+t];return this}set(e,t,n,s){let r=this.elements;return r[0]=e,r[2]=t,r[1]=n,r[3]=s,this}};Xu.prototype.isMatrix2=!0;var ou=Xu;var Zf=new W,ml=new W,Gr=new W,Wr=new W,Qh=new W,D_=new W,N_=new W,ma=class{constructor(e=new W,t=new W){this.start=e,this.end=t}set(e,t){return this.start.copy(e),this.end.copy(t),this}copy(e){return this.start.copy(e.start),this.end.copy(e.end),this}getCenter(e){return e.addVectors(this.start,this.end).multiplyScalar(.5)}delta(e){return e.subVectors(this.end,this.start)}distanceSq(){return this.start.distanceToSquared(this.end)}distance(){return this.start.distanceTo(this.end)}at(e,t){return this.delta(t).multiplyScalar(e).add(this.start)}closestPointToPointParameter(e,t){Zf.subVectors(e,this.start),ml.subVectors(this.end,this.start);let n=ml.dot(ml);if(n===0)return 0;let r=ml.dot(Zf)/n;return t&&(r=lt(r,0,1)),r}closestPointToPoint(e,t,n){let s=this.closestPointToPointParameter(e,t);return this.delta(n).multiplyScalar(s).add(this.start)}distanceSqToLine3(e,t=D_,n=N_){let s=10000000000000001e-32,r,o,a=this.start,c=e.start,l=this.end,d=e.end;Gr.subVectors(l,a),Wr.subVectors(d,c),Qh.subVectors(a,c);let u=Gr.dot(Gr),h=Wr.dot(Wr),m=Wr.dot(Qh);if(u<=s&&h<=s)return t.copy(a),n.copy(c),t.distanceToSquared(n);if(u<=s)r=0,o=m/h,o=lt(o,0,1);else{let g=Gr.dot(Qh);if(h<=s)o=0,r=lt(-g/u,0,1);else{let v=Gr.dot(Wr),p=u*h-v*v;p!==0?r=lt((v*m-g*h)/p,0,1):r=0,o=(v*r+m)/h,o<0?(o=0,r=lt(-g/u,0,1)):o>1&&(o=1,r=lt((v-g)/u,0,1))}}return t.copy(a).addScaledVector(Gr,r),n.copy(c).addScaledVector(Wr,o),t.distanceToSquared(n)}applyMatrix4(e){return this.start.applyMatrix4(e),this.end.applyMatrix4(e),this}equals(e){return e.start.equals(this.start)&&e.end.equals(this.end)}clone(){return new this.constructor().copy(this)}};var ga=class extends ea{constructor(e=10,t=10,n=4473924,s=8947848){n=new ct(n),s=new ct(s);let r=t/2,o=e/t,a=e/2,c=[],l=[];for(let h=0,m=0,g=-a;h<=t;h++,g+=o){c.push(-a,0,g,a,0,g),c.push(g,0,-a,g,0,a);let v=h===r?n:s;v.toArray(l,m),m+=3,v.toArray(l,m),m+=3,v.toArray(l,m),m+=3,v.toArray(l,m),m+=3}let d=new An;d.setAttribute("position",new Ot(c,3)),d.setAttribute("color",new Ot(l,3));let u=new xs({vertexColors:!0,toneMapped:!1});super(d,u),this.type="GridHelper"}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}};var _a=class extends ea{constructor(e=1){let t=[0,0,0,e,0,0,0,0,0,0,e,0,0,0,0,0,0,e],n=[1,0,0,1,.6,0,0,1,0,.6,1,0,0,0,1,0,.6,1],s=new An;s.setAttribute("position",new Ot(t,3)),s.setAttribute("color",new Ot(n,3));let r=new xs({vertexColors:!0,toneMapped:!1});super(s,r),this.type="AxesHelper"}setColors(e,t,n){let s=new ct,r=this.geometry.attributes.color.array;return s.set(e),s.toArray(r,0),s.toArray(r,3),s.set(t),s.toArray(r,6),s.toArray(r,9),s.set(n),s.toArray(r,12),s.toArray(r,15),this.geometry.attributes.color.needsUpdate=!0,this}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}};var xa=class extends Ci{constructor(e,t=null){super(),this.object=e,this.domElement=t,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(e){this.domElement!==null&&this.disconnect(),this.domElement=e}disconnect(){}dispose(){}update(){}};function Vu(i,e,t,n){let s=U_(n);switch(t){case Tu:return i*e;case Ru:return i*e/s.components*s.byteLength;case sc:return i*e/s.components*s.byteLength;case $s:return i*e*2/s.components*s.byteLength;case rc:return i*e*2/s.components*s.byteLength;case Au:return i*e*3/s.components*s.byteLength;case Ui:return i*e*4/s.components*s.byteLength;case oc:return i*e*4/s.components*s.byteLength;case ba:case Sa:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*8;case Ma:case wa:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*16;case lc:case hc:return Math.max(i,16)*Math.max(e,8)/4;case ac:case cc:return Math.max(i,8)*Math.max(e,8)/2;case uc:case dc:case pc:case mc:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*8;case fc:case Ea:case gc:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*16;case _c:return Math.floor((i+3)/4)*Math.floor((e+3)/4)*16;case xc:return Math.floor((i+4)/5)*Math.floor((e+3)/4)*16;case vc:return Math.floor((i+4)/5)*Math.floor((e+4)/5)*16;case yc:return Math.floor((i+5)/6)*Math.floor((e+4)/5)*16;case bc:return Math.floor((i+5)/6)*Math.floor((e+5)/6)*16;case Sc:return Math.floor((i+7)/8)*Math.floor((e+4)/5)*16;case Mc:return Math.floor((i+7)/8)*Math.floor((e+5)/6)*16;case wc:return Math.floor((i+7)/8)*Math.floor((e+7)/8)*16;case Ec:return Math.floor((i+9)/10)*Math.floor((e+4)/5)*16;case Tc:return Math.floor((i+9)/10)*Math.floor((e+5)/6)*16;case Ac:return Math.floor((i+9)/10)*Math.floor((e+7)/8)*16;case Rc:return Math.floor((i+9)/10)*Math.floor((e+9)/10)*16;case Cc:return Math.floor((i+11)/12)*Math.floor((e+9)/10)*16;case Pc:return Math.floor((i+11)/12)*Math.floor((e+11)/12)*16;case Ic:case Lc:case Dc:return Math.ceil(i/4)*Math.ceil(e/4)*16;case Nc:case Uc:return Math.ceil(i/4)*Math.ceil(e/4)*8;case Ta:case Fc:return Math.ceil(i/4)*Math.ceil(e/4)*16}throw new Error(`Unable to determine texture byte length for ${t} format.`)}function U_(i){switch(i){case Qn:case Su:return{byteLength:1,components:1};case ro:case Mu:case Ni:return{byteLength:2,components:1};case nc:case ic:return{byteLength:2,components:4};case Li:case tc:case Di:return{byteLength:4,components:1};case wu:case Eu:return{byteLength:4,components:3}}throw new Error(`THREE.TextureUtils: Unknown texture type ${i}.`)}typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:"187"}}));typeof window<"u"&&(window.__THREE__?Ye("WARNING: Multiple instances of Three.js being imported."):window.__THREE__="187");function nm(){let i=null,e=!1,t=null,n=null;function s(r,o){n=i.requestAnimationFrame(s),t(r,o)}return{start:function(){e!==!0&&t!==null&&i!==null&&(n=i.requestAnimationFrame(s),e=!0)},stop:function(){i!==null&&i.cancelAnimationFrame(n),e=!1},setAnimationLoop:function(r){t=r},setContext:function(r){i=r}}}function O_(i){let e=new WeakMap;function t(a,c){let l=a.array,d=a.usage,u=l.byteLength,h=i.createBuffer();i.bindBuffer(c,h),i.bufferData(c,l,d),a.onUploadCallback();let m;if(l instanceof Float32Array)m=i.FLOAT;else if(typeof Float16Array<"u"&&l instanceof Float16Array)m=i.HALF_FLOAT;else if(l instanceof Uint16Array)a.isFloat16BufferAttribute?m=i.HALF_FLOAT:m=i.UNSIGNED_SHORT;else if(l instanceof Int16Array)m=i.SHORT;else if(l instanceof Uint32Array)m=i.UNSIGNED_INT;else if(l instanceof Int32Array)m=i.INT;else if(l instanceof Int8Array)m=i.BYTE;else if(l instanceof Uint8Array)m=i.UNSIGNED_BYTE;else if(l instanceof Uint8ClampedArray)m=i.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+l);return{buffer:h,type:m,bytesPerElement:l.BYTES_PER_ELEMENT,version:a.version,size:u}}function n(a,c,l){let d=c.array,u=c.updateRanges;if(i.bindBuffer(l,a),u.length===0)i.bufferSubData(l,0,d);else{u.sort((m,g)=>m.start-g.start);let h=0;for(let m=1;m<u.length;m++){let g=u[h],v=u[m];v.start<=g.start+g.count+1?g.count=Math.max(g.count,v.start+v.count-g.start):(++h,u[h]=v)}u.length=h+1;for(let m=0,g=u.length;m<g;m++){let v=u[m];i.bufferSubData(l,v.start*d.BYTES_PER_ELEMENT,d,v.start,v.count)}c.clearUpdateRanges()}c.onUploadCallback()}function s(a){return a.isInterleavedBufferAttribute&&(a=a.data),e.get(a)}function r(a){a.isInterleavedBufferAttribute&&(a=a.data);let c=e.get(a);c&&(i.deleteBuffer(c.buffer),e.delete(a))}function o(a,c){if(a.isInterleavedBufferAttribute&&(a=a.data),a.isGLBufferAttribute){let d=e.get(a);(!d||d.version<a.version)&&e.set(a,{buffer:a.buffer,type:a.type,bytesPerElement:a.elementSize,version:a.version});return}let l=e.get(a);if(l===void 0)e.set(a,t(a,c));else if(l.version<a.version){if(l.size!==a.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");n(l.buffer,a,c),l.version=a.version}}return{get:s,remove:r,update:o}}var B_=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,k_=`#ifdef USE_ALPHAHASH
	const float ALPHA_HASH_SCALE = 0.05;
	float hash2D( vec2 value ) {
		return fract( 1.0e4 * sin( 17.0 * value.x + 0.1 * value.y ) * ( 0.1 + abs( sin( 13.0 * value.y + value.x ) ) ) );
	}
	float hash3D( vec3 value ) {
		return hash2D( vec2( hash2D( value.xy ), value.z ) );
	}
	float getAlphaHashThreshold( vec3 position ) {
		float maxDeriv = max(
			length( dFdx( position.xyz ) ),
			length( dFdy( position.xyz ) )
		);
		float pixScale = 1.0 / ( ALPHA_HASH_SCALE * maxDeriv );
		vec2 pixScales = vec2(
			exp2( floor( log2( pixScale ) ) ),
			exp2( ceil( log2( pixScale ) ) )
		);
		vec2 alpha = vec2(
			hash3D( floor( pixScales.x * position.xyz ) ),
			hash3D( floor( pixScales.y * position.xyz ) )
		);
		float lerpFactor = fract( log2( pixScale ) );
		float x = ( 1.0 - lerpFactor ) * alpha.x + lerpFactor * alpha.y;
		float a = min( lerpFactor, 1.0 - lerpFactor );
		vec3 cases = vec3(
			x * x / ( 2.0 * a * ( 1.0 - a ) ),
			( x - 0.5 * a ) / ( 1.0 - a ),
			1.0 - ( ( 1.0 - x ) * ( 1.0 - x ) / ( 2.0 * a * ( 1.0 - a ) ) )
		);
		float threshold = ( x < ( 1.0 - a ) )
			? ( ( x < a ) ? cases.x : cases.y )
			: cases.z;
		return clamp( threshold , 1.0e-6, 1.0 );
	}
#endif`,z_=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,V_=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,H_=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,G_=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,W_=`#ifdef USE_AOMAP
	float ambientOcclusion = ( texture2D( aoMap, vAoMapUv ).r - 1.0 ) * aoMapIntensity + 1.0;
	reflectedLight.indirectDiffuse *= ambientOcclusion;
	#if defined( USE_CLEARCOAT ) 
		clearcoatSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_SHEEN ) 
		sheenSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_ENVMAP ) && defined( STANDARD )
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		reflectedLight.indirectSpecular *= computeSpecularOcclusion( dotNV, ambientOcclusion, material.roughness );
	#endif
#endif`,$_=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,X_=`#ifdef USE_BATCHING
	#if ! defined( GL_ANGLE_multi_draw )
	#define gl_DrawID _gl_DrawID
	uniform int _gl_DrawID;
	#endif
	uniform highp sampler2D batchingTexture;
	uniform highp usampler2D batchingIdTexture;
	mat4 getBatchingMatrix( const in float i ) {
		int size = textureSize( batchingTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( batchingTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( batchingTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( batchingTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( batchingTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
	float getIndirectIndex( const in int i ) {
		int size = textureSize( batchingIdTexture, 0 ).x;
		int x = i % size;
		int y = i / size;
		return float( texelFetch( batchingIdTexture, ivec2( x, y ), 0 ).r );
	}
#endif
#ifdef USE_BATCHING_COLOR
	uniform sampler2D batchingColorTexture;
	vec4 getBatchingColor( const in float i ) {
		int size = textureSize( batchingColorTexture, 0 ).x;
		int j = int( i );
		int x = j % size;
		int y = j / size;
		return texelFetch( batchingColorTexture, ivec2( x, y ), 0 );
	}
#endif`,q_=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,Y_=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,Z_=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,J_=`float G_BlinnPhong_Implicit( ) {
	return 0.25;
}
float D_BlinnPhong( const in float shininess, const in float dotNH ) {
	return RECIPROCAL_PI * ( shininess * 0.5 + 1.0 ) * pow( dotNH, shininess );
}
vec3 BRDF_BlinnPhong( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 specularColor, const in float shininess ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( specularColor, 1.0, dotVH );
	float G = G_BlinnPhong_Implicit( );
	float D = D_BlinnPhong( shininess, dotNH );
	return F * ( G * D );
} // validated`,K_=`#ifdef USE_IRIDESCENCE
	const mat3 XYZ_TO_REC709 = mat3(
		 3.2404542, -0.9692660,  0.0556434,
		-1.5371385,  1.8760108, -0.2040259,
		-0.4985314,  0.0415560,  1.0572252
	);
	vec3 Fresnel0ToIor( vec3 fresnel0 ) {
		vec3 sqrtF0 = sqrt( fresnel0 );
		return ( vec3( 1.0 ) + sqrtF0 ) / ( vec3( 1.0 ) - sqrtF0 );
	}
	vec3 IorToFresnel0( vec3 transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - vec3( incidentIor ) ) / ( transmittedIor + vec3( incidentIor ) ) );
	}
	float IorToFresnel0( float transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - incidentIor ) / ( transmittedIor + incidentIor ));
	}
	vec3 evalSensitivity( float OPD, vec3 shift ) {
		float phase = 2.0 * PI * OPD * 1.0e-9;
		vec3 val = vec3( 5.4856e-13, 4.4201e-13, 5.2481e-13 );
		vec3 pos = vec3( 1.6810e+06, 1.7953e+06, 2.2084e+06 );
		vec3 var = vec3( 4.3278e+09, 9.3046e+09, 6.6121e+09 );
		vec3 xyz = val * sqrt( 2.0 * PI * var ) * cos( pos * phase + shift ) * exp( - pow2( phase ) * var );
		xyz.x += 9.7470e-14 * sqrt( 2.0 * PI * 4.5282e+09 ) * cos( 2.2399e+06 * phase + shift[ 0 ] ) * exp( - 4.5282e+09 * pow2( phase ) );
		xyz /= 1.0685e-7;
		vec3 rgb = XYZ_TO_REC709 * xyz;
		return rgb;
	}
	vec3 evalIridescence( float outsideIOR, float eta2, float cosTheta1, float thinFilmThickness, vec3 baseF0 ) {
		vec3 I;
		float iridescenceIOR = mix( outsideIOR, eta2, smoothstep( 0.0, 0.03, thinFilmThickness ) );
		float sinTheta2Sq = pow2( outsideIOR / iridescenceIOR ) * ( 1.0 - pow2( cosTheta1 ) );
		float cosTheta2Sq = 1.0 - sinTheta2Sq;
		if ( cosTheta2Sq < 0.0 ) {
			return vec3( 1.0 );
		}
		float cosTheta2 = sqrt( cosTheta2Sq );
		float R0 = IorToFresnel0( iridescenceIOR, outsideIOR );
		float R12 = F_Schlick( R0, 1.0, cosTheta1 );
		float T121 = 1.0 - R12;
		float phi12 = 0.0;
		if ( iridescenceIOR < outsideIOR ) phi12 = PI;
		float phi21 = PI - phi12;
		vec3 baseIOR = Fresnel0ToIor( clamp( baseF0, 0.0, 0.9999 ) );		vec3 R1 = IorToFresnel0( baseIOR, iridescenceIOR );
		vec3 R23 = F_Schlick( R1, 1.0, cosTheta2 );
		vec3 phi23 = vec3( 0.0 );
		if ( baseIOR[ 0 ] < iridescenceIOR ) phi23[ 0 ] = PI;
		if ( baseIOR[ 1 ] < iridescenceIOR ) phi23[ 1 ] = PI;
		if ( baseIOR[ 2 ] < iridescenceIOR ) phi23[ 2 ] = PI;
		float OPD = 2.0 * iridescenceIOR * thinFilmThickness * cosTheta2;
		vec3 phi = vec3( phi21 ) + phi23;
		vec3 R123 = clamp( R12 * R23, 1e-5, 0.9999 );
		vec3 r123 = sqrt( R123 );
		vec3 Rs = pow2( T121 ) * R23 / ( vec3( 1.0 ) - R123 );
		vec3 C0 = R12 + Rs;
		I = C0;
		vec3 Cm = Rs - T121;
		for ( int m = 1; m <= 2; ++ m ) {
			Cm *= r123;
			vec3 Sm = 2.0 * evalSensitivity( float( m ) * OPD, float( m ) * phi );
			I += Cm * Sm;
		}
		return max( I, vec3( 0.0 ) );
	}
#endif`,j_=`#ifdef USE_BUMPMAP
	uniform sampler2D bumpMap;
	uniform float bumpScale;
	vec2 dHdxy_fwd() {
		vec2 dSTdx = dFdx( vBumpMapUv );
		vec2 dSTdy = dFdy( vBumpMapUv );
		float Hll = bumpScale * texture2D( bumpMap, vBumpMapUv ).x;
		float dBx = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdx ).x - Hll;
		float dBy = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdy ).x - Hll;
		return vec2( dBx, dBy );
	}
	vec3 perturbNormalArb( vec3 surf_pos, vec3 surf_norm, vec2 dHdxy, float faceDirection ) {
		vec3 vSigmaX = normalize( dFdx( surf_pos.xyz ) );
		vec3 vSigmaY = normalize( dFdy( surf_pos.xyz ) );
		vec3 vN = surf_norm;
		vec3 R1 = cross( vSigmaY, vN );
		vec3 R2 = cross( vN, vSigmaX );
		float fDet = dot( vSigmaX, R1 ) * faceDirection;
		vec3 vGrad = sign( fDet ) * ( dHdxy.x * R1 + dHdxy.y * R2 );
		return normalize( abs( fDet ) * surf_norm - vGrad );
	}
#endif`,Q_=`#if NUM_CLIPPING_PLANES > 0
	vec4 plane;
	#ifdef ALPHA_TO_COVERAGE
		float distanceToPlane, distanceGradient;
		float clipOpacity = 1.0;
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
			distanceGradient = fwidth( distanceToPlane ) / 2.0;
			clipOpacity *= smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			if ( clipOpacity == 0.0 ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			float unionClipOpacity = 1.0;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
				distanceGradient = fwidth( distanceToPlane ) / 2.0;
				unionClipOpacity *= 1.0 - smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			}
			#pragma unroll_loop_end
			clipOpacity *= 1.0 - unionClipOpacity;
		#endif
		diffuseColor.a *= clipOpacity;
		if ( diffuseColor.a == 0.0 ) discard;
	#else
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			if ( dot( vClipPosition, plane.xyz ) > plane.w ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			bool clipped = true;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				clipped = ( dot( vClipPosition, plane.xyz ) > plane.w ) && clipped;
			}
			#pragma unroll_loop_end
			if ( clipped ) discard;
		#endif
	#endif
#endif`,ex=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,tx=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,nx=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,ix=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#endif`,sx=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#endif`,rx=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec4 vColor;
#endif`,ox=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	vColor = vec4( 1.0 );
#endif
#ifdef USE_COLOR_ALPHA
	vColor *= color;
#elif defined( USE_COLOR )
	vColor.rgb *= color;
#endif
#ifdef USE_INSTANCING_COLOR
	vColor.rgb *= instanceColor.rgb;
#endif
#ifdef USE_BATCHING_COLOR
	vColor *= getBatchingColor( getIndirectIndex( gl_DrawID ) );
#endif`,ax=`#define PI 3.141592653589793
#define PI2 6.283185307179586
#define PI_HALF 1.5707963267948966
#define RECIPROCAL_PI 0.3183098861837907
#define RECIPROCAL_PI2 0.15915494309189535
#define EPSILON 1e-6
#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
#define whiteComplement( a ) ( 1.0 - saturate( a ) )
float pow2( const in float x ) { return x*x; }
vec3 pow2( const in vec3 x ) { return x*x; }
float pow3( const in float x ) { return x*x*x; }
float pow4( const in float x ) { float x2 = x*x; return x2*x2; }
float max3( const in vec3 v ) { return max( max( v.x, v.y ), v.z ); }
float average( const in vec3 v ) { return dot( v, vec3( 0.3333333 ) ); }
highp float rand( const in vec2 uv ) {
	const highp float a = 12.9898, b = 78.233, c = 43758.5453;
	highp float dt = dot( uv.xy, vec2( a,b ) ), sn = mod( dt, PI );
	return fract( sin( sn ) * c );
}
#ifdef HIGH_PRECISION
	float precisionSafeLength( vec3 v ) { return length( v ); }
#else
	float precisionSafeLength( vec3 v ) {
		float maxComponent = max3( abs( v ) );
		return length( v / maxComponent ) * maxComponent;
	}
#endif
struct IncidentLight {
	vec3 color;
	vec3 direction;
	bool visible;
};
struct ReflectedLight {
	vec3 directDiffuse;
	vec3 directSpecular;
	vec3 indirectDiffuse;
	vec3 indirectSpecular;
};
#ifdef USE_ALPHAHASH
	varying vec3 vPosition;
#endif
vec3 transformDirection( in vec3 dir, in mat4 matrix ) {
	return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );
}
#define inverseTransformDirection transformDirectionByInverseViewMatrix
vec3 transformNormalByInverseViewMatrix( in vec3 normal, in mat4 viewMatrix ) {
	return normalize( ( vec4( normal, 0.0 ) * viewMatrix ).xyz );
}
vec3 transformDirectionByInverseViewMatrix( in vec3 dir, in mat4 viewMatrix ) {
	return normalize( ( vec4( dir, 0.0 ) * viewMatrix ).xyz );
}
bool isPerspectiveMatrix( mat4 m ) {
	return m[ 2 ][ 3 ] == - 1.0;
}
vec2 equirectUv( in vec3 dir ) {
	float u = atan( dir.z, dir.x ) * RECIPROCAL_PI2 + 0.5;
	float v = asin( clamp( dir.y, - 1.0, 1.0 ) ) * RECIPROCAL_PI + 0.5;
	return vec2( u, v );
}
vec3 BRDF_Lambert( const in vec3 diffuseColor ) {
	return RECIPROCAL_PI * diffuseColor;
}
vec3 F_Schlick( const in vec3 f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
}
float F_Schlick( const in float f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
} // validated`,lx=`vec3 transformedNormal = objectNormal;
#ifdef USE_TANGENT
	vec3 transformedTangent = objectTangent;
#endif
#ifdef USE_BATCHING
	mat3 bm = mat3( batchingMatrix );
	transformedNormal /= vec3( dot( bm[ 0 ], bm[ 0 ] ), dot( bm[ 1 ], bm[ 1 ] ), dot( bm[ 2 ], bm[ 2 ] ) );
	transformedNormal = bm * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = bm * transformedTangent;
	#endif
#endif
#ifdef USE_INSTANCING
	mat3 im = mat3( instanceMatrix );
	transformedNormal /= vec3( dot( im[ 0 ], im[ 0 ] ), dot( im[ 1 ], im[ 1 ] ), dot( im[ 2 ], im[ 2 ] ) );
	transformedNormal = im * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = im * transformedTangent;
	#endif
#endif
transformedNormal = normalMatrix * transformedNormal;
#ifdef FLIP_SIDED
	transformedNormal = - transformedNormal;
#endif
#ifdef USE_TANGENT
	transformedTangent = ( modelViewMatrix * vec4( transformedTangent, 0.0 ) ).xyz;
#endif`,cx=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,hx=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,ux=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,dx=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,fx="gl_FragColor = linearToOutputTexel( gl_FragColor );",px=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,mx=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vec3 cameraToFrag;
		if ( isOrthographic ) {
			cameraToFrag = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToFrag = normalize( vWorldPosition - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vec3 reflectVec = reflect( cameraToFrag, worldNormal );
		#else
			vec3 reflectVec = refract( cameraToFrag, worldNormal, refractionRatio );
		#endif
	#else
		vec3 reflectVec = vReflect;
	#endif
	#ifdef ENVMAP_TYPE_CUBE
		vec4 envColor = textureCube( envMap, envMapRotation * reflectVec );
		#ifdef ENVMAP_BLENDING_MULTIPLY
			outgoingLight = mix( outgoingLight, outgoingLight * envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_MIX )
			outgoingLight = mix( outgoingLight, envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_ADD )
			outgoingLight += envColor.xyz * specularStrength * reflectivity;
		#endif
	#endif
#endif`,gx=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform mat3 envMapRotation;
	uniform samplerCube envMap;
	#ifdef ENVMAP_TYPE_PMREM
		float roughnessToMip( const in float roughness ) {
			float r = clamp( roughness, 0.0, 1.0 );
			return ENVMAP_MAX_LOD * r * ( 2.0 - r );
		}
	#endif
#endif`,_x=`#ifdef USE_ENVMAP
	uniform float reflectivity;
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		varying vec3 vWorldPosition;
		uniform float refractionRatio;
	#else
		varying vec3 vReflect;
	#endif
#endif`,xx=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,vx=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vWorldPosition = worldPosition.xyz;
	#else
		vec3 cameraToVertex;
		if ( isOrthographic ) {
			cameraToVertex = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToVertex = normalize( worldPosition.xyz - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vReflect = reflect( cameraToVertex, worldNormal );
		#else
			vReflect = refract( cameraToVertex, worldNormal, refractionRatio );
		#endif
	#endif
#endif`,yx=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,bx=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,Sx=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,Mx=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,wx=`#ifdef USE_GRADIENTMAP
	uniform sampler2D gradientMap;
#endif
vec3 getGradientIrradiance( vec3 normal, vec3 lightDirection ) {
	float dotNL = dot( normal, lightDirection );
	vec2 coord = vec2( dotNL * 0.5 + 0.5, 0.0 );
	#ifdef USE_GRADIENTMAP
		return vec3( texture2D( gradientMap, coord ).r );
	#else
		vec2 fw = fwidth( coord ) * 0.5;
		return mix( vec3( 0.7 ), vec3( 1.0 ), smoothstep( 0.7 - fw.x, 0.7 + fw.x, coord.x ) );
	#endif
}`,Ex=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,Tx=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,Ax=`varying vec3 vViewPosition;
struct LambertMaterial {
	vec3 diffuseColor;
	float specularStrength;
};
void RE_Direct_Lambert( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Lambert( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Lambert
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,Rx=`uniform bool receiveShadow;
uniform vec3 ambientLightColor;
#if defined( USE_LIGHT_PROBES )
	uniform vec3 lightProbe[ 9 ];
#endif
vec3 shGetIrradianceAt( in vec3 normal, in vec3 shCoefficients[ 9 ] ) {
	float x = normal.x, y = normal.y, z = normal.z;
	vec3 result = shCoefficients[ 0 ] * 0.886227;
	result += shCoefficients[ 1 ] * 2.0 * 0.511664 * y;
	result += shCoefficients[ 2 ] * 2.0 * 0.511664 * z;
	result += shCoefficients[ 3 ] * 2.0 * 0.511664 * x;
	result += shCoefficients[ 4 ] * 2.0 * 0.429043 * x * y;
	result += shCoefficients[ 5 ] * 2.0 * 0.429043 * y * z;
	result += shCoefficients[ 6 ] * ( 0.743125 * z * z - 0.247708 );
	result += shCoefficients[ 7 ] * 2.0 * 0.429043 * x * z;
	result += shCoefficients[ 8 ] * 0.429043 * ( x * x - y * y );
	return result;
}
vec3 getLightProbeIrradiance( const in vec3 lightProbe[ 9 ], const in vec3 normal ) {
	vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec3 irradiance = shGetIrradianceAt( worldNormal, lightProbe );
	return irradiance;
}
vec3 getAmbientLightIrradiance( const in vec3 ambientLightColor ) {
	vec3 irradiance = ambientLightColor;
	return irradiance;
}
float getDistanceAttenuation( const in float lightDistance, const in float cutoffDistance, const in float decayExponent ) {
	float distanceFalloff = 1.0 / max( pow( lightDistance, decayExponent ), 0.01 );
	if ( cutoffDistance > 0.0 ) {
		distanceFalloff *= pow2( saturate( 1.0 - pow4( lightDistance / cutoffDistance ) ) );
	}
	return distanceFalloff;
}
float getSpotAttenuation( const in float coneCosine, const in float penumbraCosine, const in float angleCosine ) {
	return smoothstep( coneCosine, penumbraCosine, angleCosine );
}
#if NUM_SUN_LIGHTS > 0
	struct SunLight {
		vec3 direction;
		vec3 color;
	};
	uniform SunLight sunLights[ NUM_SUN_LIGHTS ];
	void getSunLightInfo( const in SunLight sunLight, out IncidentLight light ) {
		light.color = sunLight.color;
		light.direction = sunLight.direction;
		light.visible = true;
	}
#endif
#if NUM_DIR_LIGHTS > 0
	struct DirectionalLight {
		vec3 direction;
		vec3 color;
	};
	uniform DirectionalLight directionalLights[ NUM_DIR_LIGHTS ];
	void getDirectionalLightInfo( const in DirectionalLight directionalLight, out IncidentLight light ) {
		light.color = directionalLight.color;
		light.direction = directionalLight.direction;
		light.visible = true;
	}
#endif
#if NUM_POINT_LIGHTS > 0
	struct PointLight {
		vec3 position;
		vec3 color;
		float distance;
		float decay;
	};
	uniform PointLight pointLights[ NUM_POINT_LIGHTS ];
	void getPointLightInfo( const in PointLight pointLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = pointLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float lightDistance = length( lVector );
		light.color = pointLight.color;
		light.color *= getDistanceAttenuation( lightDistance, pointLight.distance, pointLight.decay );
		light.visible = ( light.color != vec3( 0.0 ) );
	}
#endif
#if NUM_SPOT_LIGHTS > 0
	struct SpotLight {
		vec3 position;
		vec3 direction;
		vec3 color;
		float distance;
		float decay;
		float coneCos;
		float penumbraCos;
	};
	uniform SpotLight spotLights[ NUM_SPOT_LIGHTS ];
	void getSpotLightInfo( const in SpotLight spotLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = spotLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float angleCos = dot( light.direction, spotLight.direction );
		float spotAttenuation = getSpotAttenuation( spotLight.coneCos, spotLight.penumbraCos, angleCos );
		if ( spotAttenuation > 0.0 ) {
			float lightDistance = length( lVector );
			light.color = spotLight.color * spotAttenuation;
			light.color *= getDistanceAttenuation( lightDistance, spotLight.distance, spotLight.decay );
			light.visible = ( light.color != vec3( 0.0 ) );
		} else {
			light.color = vec3( 0.0 );
			light.visible = false;
		}
	}
#endif
#if NUM_RECT_AREA_LIGHTS > 0
	struct RectAreaLight {
		vec3 color;
		vec3 position;
		vec3 halfWidth;
		vec3 halfHeight;
	};
	uniform sampler2D ltc_1;	uniform sampler2D ltc_2;
	uniform RectAreaLight rectAreaLights[ NUM_RECT_AREA_LIGHTS ];
#endif
#if NUM_HEMI_LIGHTS > 0
	struct HemisphereLight {
		vec3 direction;
		vec3 skyColor;
		vec3 groundColor;
	};
	uniform HemisphereLight hemisphereLights[ NUM_HEMI_LIGHTS ];
	vec3 getHemisphereLightIrradiance( const in HemisphereLight hemiLight, const in vec3 normal ) {
		float dotNL = dot( normal, hemiLight.direction );
		float hemiDiffuseWeight = 0.5 * dotNL + 0.5;
		vec3 irradiance = mix( hemiLight.groundColor, hemiLight.skyColor, hemiDiffuseWeight );
		return irradiance;
	}
#endif
#include <lightprobes_pars_fragment>`,Cx=`#ifdef USE_ENVMAP
	vec3 getIBLIrradiance( const in vec3 normal ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * worldNormal, ENVMAP_MAX_LOD );
			return PI * envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	vec3 getIBLRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 reflectVec = reflect( - viewDir, normal );
			reflectVec = normalize( mix( reflectVec, normal, pow4( roughness ) ) );
			reflectVec = transformDirectionByInverseViewMatrix( reflectVec, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * reflectVec, roughnessToMip( roughness ) );
			return envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	#ifdef USE_RETROREFLECTION
		vec3 getIBLRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 retroVec = normalize( mix( viewDir, normal, pow4( roughness ) ) );
				retroVec = transformDirectionByInverseViewMatrix( retroVec, viewMatrix );
				vec4 envMapColor = textureLod( envMap, envMapRotation * retroVec, roughnessToMip( roughness ) );
				return envMapColor.rgb * envMapIntensity;
			#else
				return vec3( 0.0 );
			#endif
		}
	#endif
	#ifdef USE_ANISOTROPY
		vec3 getIBLAnisotropyRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 bentNormal = cross( bitangent, viewDir );
				bentNormal = normalize( cross( bentNormal, bitangent ) );
				bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
				return getIBLRadiance( viewDir, bentNormal, roughness );
			#else
				return vec3( 0.0 );
			#endif
		}
		#ifdef USE_RETROREFLECTION
			vec3 getIBLAnisotropyRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
				#ifdef ENVMAP_TYPE_PMREM
					vec3 bentNormal = cross( bitangent, viewDir );
					bentNormal = normalize( cross( bentNormal, bitangent ) );
					bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
					return getIBLRetroRadiance( viewDir, bentNormal, roughness );
				#else
					return vec3( 0.0 );
				#endif
			}
		#endif
	#endif
#endif`,Px=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,Ix=`varying vec3 vViewPosition;
struct ToonMaterial {
	vec3 diffuseColor;
};
void RE_Direct_Toon( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 irradiance = getGradientIrradiance( geometryNormal, directLight.direction ) * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Toon( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Toon
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,Lx=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,Dx=`varying vec3 vViewPosition;
struct BlinnPhongMaterial {
	vec3 diffuseColor;
	vec3 specularColor;
	float specularShininess;
	float specularStrength;
};
void RE_Direct_BlinnPhong( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
	reflectedLight.directSpecular += irradiance * BRDF_BlinnPhong( directLight.direction, geometryViewDir, geometryNormal, material.specularColor, material.specularShininess ) * material.specularStrength;
}
void RE_IndirectDiffuse_BlinnPhong( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_BlinnPhong
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,Nx=`PhysicalMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.diffuseContribution = diffuseColor.rgb * ( 1.0 - metalnessFactor );
material.metalness = metalnessFactor;
vec3 dxy = max( abs( dFdx( nonPerturbedNormal ) ), abs( dFdy( nonPerturbedNormal ) ) );
float geometryRoughness = max( max( dxy.x, dxy.y ), dxy.z );
material.roughness = max( roughnessFactor, 0.045 );
material.roughness += geometryRoughness;
material.roughness = min( material.roughness, 1.0 );
#ifdef USE_DIFFUSE_ROUGHNESS
	float diffuseRoughnessFactor = diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		diffuseRoughnessFactor *= texture2D( diffuseRoughnessMap, vDiffuseRoughnessMapUv ).r;
	#endif
	material.diffuseRoughness = saturate( diffuseRoughnessFactor );
#endif
#ifdef IOR
	material.ior = ior;
	#ifdef USE_SPECULAR
		float specularIntensityFactor = specularIntensity;
		vec3 specularColorFactor = specularColor;
		#ifdef USE_SPECULAR_COLORMAP
			specularColorFactor *= texture2D( specularColorMap, vSpecularColorMapUv ).rgb;
		#endif
		#ifdef USE_SPECULAR_INTENSITYMAP
			specularIntensityFactor *= texture2D( specularIntensityMap, vSpecularIntensityMapUv ).a;
		#endif
		material.specularF90 = mix( specularIntensityFactor, 1.0, metalnessFactor );
	#else
		float specularIntensityFactor = 1.0;
		vec3 specularColorFactor = vec3( 1.0 );
		material.specularF90 = 1.0;
	#endif
	material.specularColor = min( pow2( ( material.ior - 1.0 ) / ( material.ior + 1.0 ) ) * specularColorFactor, vec3( 1.0 ) ) * specularIntensityFactor;
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
#else
	material.specularColor = vec3( 0.04 );
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
	material.specularF90 = 1.0;
#endif
#ifdef USE_CLEARCOAT
	material.clearcoat = clearcoat;
	material.clearcoatRoughness = clearcoatRoughness;
	material.clearcoatF0 = vec3( 0.04 );
	material.clearcoatF90 = 1.0;
	#ifdef USE_CLEARCOATMAP
		material.clearcoat *= texture2D( clearcoatMap, vClearcoatMapUv ).x;
	#endif
	#ifdef USE_CLEARCOAT_ROUGHNESSMAP
		material.clearcoatRoughness *= texture2D( clearcoatRoughnessMap, vClearcoatRoughnessMapUv ).y;
	#endif
	material.clearcoat = saturate( material.clearcoat );	material.clearcoatRoughness = max( material.clearcoatRoughness, 0.045 );
	material.clearcoatRoughness += geometryRoughness;
	material.clearcoatRoughness = min( material.clearcoatRoughness, 1.0 );
#endif
#ifdef USE_DISPERSION
	material.dispersion = dispersion;
#endif
#ifdef USE_RETROREFLECTION
	material.retroreflectivity = retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	material.iridescence = iridescence;
	material.iridescenceIOR = iridescenceIOR;
	#ifdef USE_IRIDESCENCEMAP
		material.iridescence *= texture2D( iridescenceMap, vIridescenceMapUv ).r;
	#endif
	#ifdef USE_IRIDESCENCE_THICKNESSMAP
		material.iridescenceThickness = (iridescenceThicknessMaximum - iridescenceThicknessMinimum) * texture2D( iridescenceThicknessMap, vIridescenceThicknessMapUv ).g + iridescenceThicknessMinimum;
	#else
		material.iridescenceThickness = iridescenceThicknessMaximum;
	#endif
#endif
#ifdef USE_SHEEN
	material.sheenColor = sheenColor;
	#ifdef USE_SHEEN_COLORMAP
		material.sheenColor *= texture2D( sheenColorMap, vSheenColorMapUv ).rgb;
	#endif
	material.sheenRoughness = clamp( sheenRoughness, 0.0001, 1.0 );
	#ifdef USE_SHEEN_ROUGHNESSMAP
		material.sheenRoughness *= texture2D( sheenRoughnessMap, vSheenRoughnessMapUv ).a;
	#endif
#endif
#ifdef USE_ANISOTROPY
	#ifdef USE_ANISOTROPYMAP
		mat2 anisotropyMat = mat2( anisotropyVector.x, anisotropyVector.y, - anisotropyVector.y, anisotropyVector.x );
		vec3 anisotropyPolar = texture2D( anisotropyMap, vAnisotropyMapUv ).rgb;
		vec2 anisotropyV = anisotropyMat * normalize( 2.0 * anisotropyPolar.rg - vec2( 1.0 ) ) * anisotropyPolar.b;
	#else
		vec2 anisotropyV = anisotropyVector;
	#endif
	material.anisotropy = length( anisotropyV );
	if( material.anisotropy == 0.0 ) {
		anisotropyV = vec2( 1.0, 0.0 );
	} else {
		anisotropyV /= material.anisotropy;
		material.anisotropy = saturate( material.anisotropy );
	}
	material.alphaT = mix( pow2( material.roughness ), 1.0, pow2( material.anisotropy ) );
	material.anisotropyT = tbn[ 0 ] * anisotropyV.x + tbn[ 1 ] * anisotropyV.y;
	material.anisotropyB = tbn[ 1 ] * anisotropyV.x - tbn[ 0 ] * anisotropyV.y;
#endif`,Ux=`uniform sampler2D dfgLUT;
struct PhysicalMaterial {
	vec3 diffuseColor;
	vec3 diffuseContribution;
	vec3 specularColor;
	vec3 specularColorBlended;
	float roughness;
	float metalness;
	float specularF90;
	float dispersion;
	vec2 dfg;
	vec3 multiScatteringCompensation;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float diffuseRoughness;
	#endif
	#ifdef USE_RETROREFLECTION
		float retroreflectivity;
	#endif
	#ifdef USE_CLEARCOAT
		float clearcoat;
		float clearcoatRoughness;
		vec3 clearcoatF0;
		float clearcoatF90;
	#endif
	#ifdef USE_IRIDESCENCE
		float iridescence;
		float iridescenceIOR;
		float iridescenceThickness;
		vec3 iridescenceFresnel;
		vec3 iridescenceF0Dielectric;
		vec3 iridescenceF0Metallic;
	#endif
	#ifdef USE_SHEEN
		vec3 sheenColor;
		float sheenRoughness;
	#endif
	#ifdef IOR
		float ior;
	#endif
	#ifdef USE_TRANSMISSION
		float transmission;
		float transmissionAlpha;
		float thickness;
		float attenuationDistance;
		vec3 attenuationColor;
	#endif
	#ifdef USE_ANISOTROPY
		float anisotropy;
		float alphaT;
		vec3 anisotropyT;
		vec3 anisotropyB;
	#endif
};
vec3 clearcoatSpecularDirect = vec3( 0.0 );
vec3 clearcoatSpecularIndirect = vec3( 0.0 );
vec3 sheenSpecularDirect = vec3( 0.0 );
vec3 sheenSpecularIndirect = vec3(0.0 );
vec3 Schlick_to_F0( const in vec3 f, const in float f90, const in float dotVH ) {
    float x = clamp( 1.0 - dotVH, 0.0, 1.0 );
    float x2 = x * x;
    float x5 = clamp( x * x2 * x2, 0.0, 0.9999 );
    return ( f - vec3( f90 ) * x5 ) / ( 1.0 - x5 );
}
#ifdef USE_DIFFUSE_ROUGHNESS
	const float EON_EPSILON = 1e-7;
	float FON_DirectionalAlbedo( const in float mu, const in float roughness, const in float A ) {
		float muComp = 1.0 - mu;
		float gOverPi = muComp * ( 0.0571085289 + muComp * ( 0.491881867 + muComp * ( - 0.332181442 + muComp * 0.0714429953 ) ) );
		return A * ( 1.0 + roughness * gOverPi );
	}
	vec3 BRDF_EON( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 diffuseColor, const in float roughness ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return BRDF_Lambert( rho );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float s = dot( lightDir, viewDir ) - dotNL * dotNV;
		float sOverT = ( s > 0.0 ) ? s / max( max( dotNL, dotNV ), EON_EPSILON ) : s;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		vec3 singleScatter = rho * RECIPROCAL_PI * A * ( 1.0 + roughness * sOverT );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		float albedoV = FON_DirectionalAlbedo( dotNV, roughness, A );
		float albedoL = FON_DirectionalAlbedo( dotNL, roughness, A );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		vec3 multiScatter = rhoMultiScatter * RECIPROCAL_PI
			* max( EON_EPSILON, 1.0 - albedoV )
			* max( EON_EPSILON, 1.0 - albedoL )
			/ max( EON_EPSILON, 1.0 - averageAlbedo );
		return singleScatter + multiScatter;
	}
	vec3 EON_DirectionalAlbedo( const in vec3 diffuseColor, const in float roughness, const in float dotNV ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return rho;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		float directionalAlbedo = FON_DirectionalAlbedo( dotNV, roughness, A );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		return rho * directionalAlbedo + rhoMultiScatter * ( 1.0 - directionalAlbedo );
	}
#endif
float V_GGX_SmithCorrelated( const in float alpha, const in float dotNL, const in float dotNV ) {
	float a2 = pow2( alpha );
	float gv = dotNL * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNV ) );
	float gl = dotNV * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNL ) );
	return 0.5 / max( gv + gl, EPSILON );
}
float D_GGX( const in float alpha, const in float dotNH ) {
	float a2 = pow2( alpha );
	float denom = pow2( dotNH ) * ( a2 - 1.0 ) + 1.0;
	return RECIPROCAL_PI * a2 / pow2( denom );
}
#ifdef USE_ANISOTROPY
	float V_GGX_SmithCorrelated_Anisotropic( const in float alphaT, const in float alphaB, const in float dotTV, const in float dotBV, const in float dotTL, const in float dotBL, const in float dotNV, const in float dotNL ) {
		float gv = dotNL * length( vec3( alphaT * dotTV, alphaB * dotBV, dotNV ) );
		float gl = dotNV * length( vec3( alphaT * dotTL, alphaB * dotBL, dotNL ) );
		return 0.5 / max( gv + gl, EPSILON );
	}
	float D_GGX_Anisotropic( const in float alphaT, const in float alphaB, const in float dotNH, const in float dotTH, const in float dotBH ) {
		float a2 = alphaT * alphaB;
		highp vec3 v = vec3( alphaB * dotTH, alphaT * dotBH, a2 * dotNH );
		highp float v2 = dot( v, v );
		float w2 = a2 / v2;
		return RECIPROCAL_PI * a2 * pow2 ( w2 );
	}
#endif
#ifdef USE_CLEARCOAT
	vec3 BRDF_GGX_Clearcoat( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material) {
		vec3 f0 = material.clearcoatF0;
		float f90 = material.clearcoatF90;
		float roughness = max( material.clearcoatRoughness, 0.045 );
		float alpha = pow2( roughness );
		vec3 halfDir = normalize( lightDir + viewDir );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float dotNH = saturate( dot( normal, halfDir ) );
		float dotVH = saturate( dot( viewDir, halfDir ) );
		vec3 F = F_Schlick( f0, f90, dotVH );
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
		return F * ( V * D );
	}
#endif
vec3 BRDF_GGX( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material ) {
	vec3 f0 = material.specularColorBlended;
	float f90 = material.specularF90;
	float roughness = max( material.roughness, 0.045 );
	float alpha = pow2( roughness );
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( f0, f90, dotVH );
	#ifdef USE_IRIDESCENCE
		F = mix( F, material.iridescenceFresnel, material.iridescence );
	#endif
	#ifdef USE_ANISOTROPY
		float dotTL = dot( material.anisotropyT, lightDir );
		float dotTV = dot( material.anisotropyT, viewDir );
		float dotTH = dot( material.anisotropyT, halfDir );
		float dotBL = dot( material.anisotropyB, lightDir );
		float dotBV = dot( material.anisotropyB, viewDir );
		float dotBH = dot( material.anisotropyB, halfDir );
		float alphaT = max( material.alphaT, alpha );
		float V = V_GGX_SmithCorrelated_Anisotropic( alphaT, alpha, dotTV, dotBV, dotTL, dotBL, dotNV, dotNL );
		float D = D_GGX_Anisotropic( alphaT, alpha, dotNH, dotTH, dotBH );
	#else
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
	#endif
	return F * ( V * D );
}
vec2 LTC_Uv( const in vec3 N, const in vec3 V, const in float roughness ) {
	const float LUT_SIZE = 64.0;
	const float LUT_SCALE = ( LUT_SIZE - 1.0 ) / LUT_SIZE;
	const float LUT_BIAS = 0.5 / LUT_SIZE;
	float dotNV = saturate( dot( N, V ) );
	vec2 uv = vec2( roughness, sqrt( 1.0 - dotNV ) );
	uv = uv * LUT_SCALE + LUT_BIAS;
	return uv;
}
float LTC_ClippedSphereFormFactor( const in vec3 f ) {
	float l = length( f );
	return max( ( l * l + f.z ) / ( l + 1.0 ), 0.0 );
}
vec3 LTC_EdgeVectorFormFactor( const in vec3 v1, const in vec3 v2 ) {
	float x = dot( v1, v2 );
	float y = abs( x );
	float a = 0.8543985 + ( 0.4965155 + 0.0145206 * y ) * y;
	float b = 3.4175940 + ( 4.1616724 + y ) * y;
	float v = a / b;
	float theta_sintheta = ( x > 0.0 ) ? v : 0.5 * inversesqrt( max( 1.0 - x * x, 1e-7 ) ) - v;
	return cross( v1, v2 ) * theta_sintheta;
}
vec3 LTC_Evaluate( const in vec3 N, const in vec3 V, const in vec3 P, const in mat3 mInv, const in vec3 rectCoords[ 4 ] ) {
	vec3 v1 = rectCoords[ 1 ] - rectCoords[ 0 ];
	vec3 v2 = rectCoords[ 3 ] - rectCoords[ 0 ];
	vec3 lightNormal = cross( v1, v2 );
	if( dot( lightNormal, P - rectCoords[ 0 ] ) < 0.0 ) return vec3( 0.0 );
	vec3 T1, T2;
	T1 = normalize( V - N * dot( V, N ) );
	T2 = - cross( N, T1 );
	mat3 mat = mInv * transpose( mat3( T1, T2, N ) );
	vec3 coords[ 4 ];
	coords[ 0 ] = mat * ( rectCoords[ 0 ] - P );
	coords[ 1 ] = mat * ( rectCoords[ 1 ] - P );
	coords[ 2 ] = mat * ( rectCoords[ 2 ] - P );
	coords[ 3 ] = mat * ( rectCoords[ 3 ] - P );
	coords[ 0 ] = normalize( coords[ 0 ] );
	coords[ 1 ] = normalize( coords[ 1 ] );
	coords[ 2 ] = normalize( coords[ 2 ] );
	coords[ 3 ] = normalize( coords[ 3 ] );
	vec3 vectorFormFactor = vec3( 0.0 );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 0 ], coords[ 1 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 1 ], coords[ 2 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 2 ], coords[ 3 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 3 ], coords[ 0 ] );
	float result = LTC_ClippedSphereFormFactor( vectorFormFactor );
	return vec3( result );
}
#if defined( USE_SHEEN )
float D_Charlie( float roughness, float dotNH ) {
	float alpha = pow2( roughness );
	float invAlpha = 1.0 / alpha;
	float cos2h = dotNH * dotNH;
	float sin2h = max( 1.0 - cos2h, 0.0078125 );
	return ( 2.0 + invAlpha ) * pow( sin2h, invAlpha * 0.5 ) / ( 2.0 * PI );
}
float V_Neubelt( float dotNV, float dotNL ) {
	return saturate( 1.0 / ( 4.0 * ( dotNL + dotNV - dotNL * dotNV ) ) );
}
vec3 BRDF_Sheen( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, vec3 sheenColor, const in float sheenRoughness ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float D = D_Charlie( sheenRoughness, dotNH );
	float V = V_Neubelt( dotNV, dotNL );
	return sheenColor * ( D * V );
}
#endif
float IBLSheenBRDF( const in vec3 normal, const in vec3 viewDir, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	float r2 = roughness * roughness;
	float rInv = 1.0 / ( roughness + 0.1 );
	float a = -1.9362 + 1.0678 * roughness + 0.4573 * r2 - 0.8469 * rInv;
	float b = -0.6014 + 0.5538 * roughness - 0.4670 * r2 - 0.1255 * rInv;
	float DG = exp( a * dotNV + b );
	return saturate( DG );
}
vec3 EnvironmentBRDF( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	vec2 fab = texture2D( dfgLUT, vec2( roughness, dotNV ) ).rg;
	return specularColor * fab.x + specularF90 * fab.y;
}
#ifdef USE_IRIDESCENCE
void computeMultiscatteringIridescence( const in vec2 fab, const in vec3 specularColor, const in float specularF90, const in float iridescence, const in vec3 iridescenceF0, inout vec3 singleScatter, inout vec3 multiScatter ) {
#else
void computeMultiscattering( const in vec2 fab, const in vec3 specularColor, const in float specularF90, inout vec3 singleScatter, inout vec3 multiScatter ) {
#endif
	#ifdef USE_IRIDESCENCE
		vec3 Fr = mix( specularColor, iridescenceF0, iridescence );
	#else
		vec3 Fr = specularColor;
	#endif
	vec3 FssEss = Fr * fab.x + specularF90 * fab.y;
	float Ess = fab.x + fab.y;
	float Ems = 1.0 - Ess;
	vec3 Favg = Fr + ( 1.0 - Fr ) * 0.047619;	vec3 Fms = FssEss * Favg / ( 1.0 - Ems * Favg );
	singleScatter += FssEss;
	multiScatter += Fms * Ems;
}
#if NUM_RECT_AREA_LIGHTS > 0
	void RE_Direct_RectArea_Physical( const in RectAreaLight rectAreaLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
		vec3 normal = geometryNormal;
		vec3 viewDir = geometryViewDir;
		vec3 position = geometryPosition;
		vec3 lightPos = rectAreaLight.position;
		vec3 halfWidth = rectAreaLight.halfWidth;
		vec3 halfHeight = rectAreaLight.halfHeight;
		vec3 lightColor = rectAreaLight.color;
		float roughness = material.roughness;
		vec3 rectCoords[ 4 ];
		rectCoords[ 0 ] = lightPos + halfWidth - halfHeight;		rectCoords[ 1 ] = lightPos - halfWidth - halfHeight;
		rectCoords[ 2 ] = lightPos - halfWidth + halfHeight;
		rectCoords[ 3 ] = lightPos + halfWidth + halfHeight;
		vec2 uv = LTC_Uv( normal, viewDir, roughness );
		vec4 t1 = texture2D( ltc_1, uv );
		vec4 t2 = texture2D( ltc_2, uv );
		mat3 mInv = mat3(
			vec3( t1.x, 0, t1.y ),
			vec3(    0, 1,    0 ),
			vec3( t1.z, 0, t1.w )
		);
		vec3 fresnel = ( material.specularColorBlended * t2.x + ( material.specularF90 - material.specularColorBlended ) * t2.y );
		reflectedLight.directSpecular += lightColor * fresnel * LTC_Evaluate( normal, viewDir, position, mInv, rectCoords );
		reflectedLight.directDiffuse += lightColor * material.diffuseContribution * LTC_Evaluate( normal, viewDir, position, mat3( 1.0 ), rectCoords );
		#ifdef USE_CLEARCOAT
			vec3 Ncc = geometryClearcoatNormal;
			vec2 uvClearcoat = LTC_Uv( Ncc, viewDir, material.clearcoatRoughness );
			vec4 t1Clearcoat = texture2D( ltc_1, uvClearcoat );
			vec4 t2Clearcoat = texture2D( ltc_2, uvClearcoat );
			mat3 mInvClearcoat = mat3(
				vec3( t1Clearcoat.x, 0, t1Clearcoat.y ),
				vec3(             0, 1,             0 ),
				vec3( t1Clearcoat.z, 0, t1Clearcoat.w )
			);
			vec3 fresnelClearcoat = material.clearcoatF0 * t2Clearcoat.x + ( material.clearcoatF90 - material.clearcoatF0 ) * t2Clearcoat.y;
			clearcoatSpecularDirect += lightColor * fresnelClearcoat * LTC_Evaluate( Ncc, viewDir, position, mInvClearcoat, rectCoords );
		#endif
	}
#endif
void RE_Direct_Physical( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	#ifdef USE_CLEARCOAT
		float dotNLcc = saturate( dot( geometryClearcoatNormal, directLight.direction ) );
		vec3 ccIrradiance = dotNLcc * directLight.color;
		clearcoatSpecularDirect += ccIrradiance * BRDF_GGX_Clearcoat( directLight.direction, geometryViewDir, geometryClearcoatNormal, material );
	#endif
	#ifdef USE_SHEEN
 
 		sheenSpecularDirect += irradiance * BRDF_Sheen( directLight.direction, geometryViewDir, geometryNormal, material.sheenColor, material.sheenRoughness );
 
 		float sheenAlbedoV = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
 		float sheenAlbedoL = IBLSheenBRDF( geometryNormal, directLight.direction, material.sheenRoughness );
 
 		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * max( sheenAlbedoV, sheenAlbedoL );
 
 		irradiance *= sheenEnergyComp;
 
 	#endif
	vec3 specularBRDF = BRDF_GGX( directLight.direction, geometryViewDir, geometryNormal, material );
	#ifdef USE_RETROREFLECTION
		vec3 retroViewDir = reflect( - geometryViewDir, geometryNormal );
		vec3 retroSpecularBRDF = BRDF_GGX( directLight.direction, retroViewDir, geometryNormal, material );
		specularBRDF = mix( specularBRDF, retroSpecularBRDF, saturate( material.retroreflectivity ) );
	#endif
	reflectedLight.directSpecular += irradiance * specularBRDF * material.multiScatteringCompensation;
	vec3 halfDir = normalize( directLight.direction + geometryViewDir );
	float dotVH = saturate( dot( geometryViewDir, halfDir ) );
	vec3 F = F_Schlick( material.specularColor, material.specularF90, dotVH );
	#ifdef USE_RETROREFLECTION
		vec3 retroHalfDir = normalize( directLight.direction + retroViewDir );
		float dotRetroVH = saturate( dot( retroViewDir, retroHalfDir ) );
		vec3 retroF = F_Schlick( material.specularColor, material.specularF90, dotRetroVH );
		F = mix( F, retroF, saturate( material.retroreflectivity ) );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		vec3 diffuseBRDF = BRDF_EON( directLight.direction, geometryViewDir, geometryNormal, material.diffuseColor, material.diffuseRoughness ) * ( 1.0 - material.metalness );
	#else
		vec3 diffuseBRDF = BRDF_Lambert( material.diffuseContribution );
	#endif
	reflectedLight.directDiffuse += irradiance * diffuseBRDF * ( 1.0 - F );
}
void RE_IndirectDiffuse_Physical( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 singleScattering = vec3( 0.0 );
	vec3 multiScattering = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScattering, multiScattering );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScattering, multiScattering );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuseAlbedo = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness );
		vec3 diffuse = irradiance * RECIPROCAL_PI * diffuseAlbedo * ( 1.0 - singleScattering - multiScattering );
	#else
		vec3 diffuse = irradiance * BRDF_Lambert( material.diffuseContribution ) * ( 1.0 - singleScattering - multiScattering );
	#endif
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		sheenSpecularIndirect += irradiance * material.sheenColor * sheenAlbedo * RECIPROCAL_PI;
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		diffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectDiffuse += diffuse;
}
void RE_IndirectSpecular_Physical( const in vec3 radiance, const in vec3 irradiance, const in vec3 clearcoatRadiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight) {
	#ifdef USE_CLEARCOAT
		clearcoatSpecularIndirect += clearcoatRadiance * EnvironmentBRDF( geometryClearcoatNormal, geometryViewDir, material.clearcoatF0, material.clearcoatF90, material.clearcoatRoughness );
	#endif
	#ifdef USE_SHEEN
		sheenSpecularIndirect += irradiance * material.sheenColor * IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness ) * RECIPROCAL_PI;
 	#endif
	vec3 singleScatteringDielectric = vec3( 0.0 );
	vec3 multiScatteringDielectric = vec3( 0.0 );
	vec3 singleScatteringMetallic = vec3( 0.0 );
	vec3 multiScatteringMetallic = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscatteringIridescence( material.dfg, material.diffuseColor, material.specularF90, material.iridescence, material.iridescenceF0Metallic, singleScatteringMetallic, multiScatteringMetallic );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscattering( material.dfg, material.diffuseColor, material.specularF90, singleScatteringMetallic, multiScatteringMetallic );
	#endif
	vec3 singleScattering = mix( singleScatteringDielectric, singleScatteringMetallic, material.metalness );
	vec3 multiScattering = mix( multiScatteringDielectric, multiScatteringMetallic, material.metalness );
	vec3 totalScatteringDielectric = singleScatteringDielectric + multiScatteringDielectric;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuse = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness ) * ( 1.0 - totalScatteringDielectric );
	#else
		vec3 diffuse = material.diffuseContribution * ( 1.0 - totalScatteringDielectric );
	#endif
	vec3 cosineWeightedIrradiance = irradiance * RECIPROCAL_PI;
	vec3 indirectSpecular = radiance * singleScattering;
	indirectSpecular += multiScattering * cosineWeightedIrradiance;
	vec3 indirectDiffuse = diffuse * cosineWeightedIrradiance;
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		indirectSpecular *= sheenEnergyComp;
		indirectDiffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectSpecular += indirectSpecular;
	reflectedLight.indirectDiffuse += indirectDiffuse;
}
#define RE_Direct				RE_Direct_Physical
#define RE_Direct_RectArea		RE_Direct_RectArea_Physical
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Physical
#define RE_IndirectSpecular		RE_IndirectSpecular_Physical
float computeSpecularOcclusion( const in float dotNV, const in float ambientOcclusion, const in float roughness ) {
	return saturate( pow( dotNV + ambientOcclusion, exp2( - 16.0 * roughness - 1.0 ) ) - 1.0 + ambientOcclusion );
}`,Fx=`
vec3 geometryPosition = - vViewPosition;
vec3 geometryNormal = normal;
vec3 geometryViewDir = ( isOrthographic ) ? vec3( 0, 0, 1 ) : normalize( vViewPosition );
vec3 geometryClearcoatNormal = vec3( 0.0 );
#ifdef USE_CLEARCOAT
	geometryClearcoatNormal = clearcoatNormal;
#endif
#ifdef USE_IRIDESCENCE
	float dotNVi = saturate( dot( normal, geometryViewDir ) );
	if ( material.iridescenceThickness == 0.0 ) {
		material.iridescence = 0.0;
	} else {
		material.iridescence = saturate( material.iridescence );
	}
	if ( material.iridescence > 0.0 ) {
		vec3 iridescenceFresnelDielectric = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor );
		vec3 iridescenceFresnelMetallic = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.diffuseColor );
		material.iridescenceFresnel = mix( iridescenceFresnelDielectric, iridescenceFresnelMetallic, material.metalness );
		material.iridescenceF0Dielectric = Schlick_to_F0( iridescenceFresnelDielectric, 1.0, dotNVi );
		material.iridescenceF0Metallic = Schlick_to_F0( iridescenceFresnelMetallic, 1.0, dotNVi );
	}
#endif
#ifdef STANDARD
	float dotNVms = saturate( dot( geometryNormal, geometryViewDir ) );
	material.dfg = texture2D( dfgLUT, vec2( material.roughness, dotNVms ) ).rg;
	#if ( NUM_SUN_LIGHTS > 0 || NUM_DIR_LIGHTS > 0 || NUM_POINT_LIGHTS > 0 || NUM_SPOT_LIGHTS > 0 )
		float EssMs = material.dfg.x + material.dfg.y;
		material.multiScatteringCompensation = 1.0 + material.specularColorBlended * ( 1.0 / EssMs - 1.0 );
	#endif
#endif
IncidentLight directLight;
#if ( NUM_POINT_LIGHTS > 0 ) && defined( RE_Direct )
	PointLight pointLight;
	#if defined( USE_SHADOWMAP ) && NUM_POINT_LIGHT_SHADOWS > 0
	PointLightShadow pointLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHTS; i ++ ) {
		pointLight = pointLights[ i ];
		getPointLightInfo( pointLight, geometryPosition, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_POINT_LIGHT_SHADOWS ) && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
		pointLightShadow = pointLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getPointShadow( pointShadowMap[ i ], pointLightShadow.shadowMapSize, pointLightShadow.shadowIntensity, pointLightShadow.shadowBias, pointLightShadow.shadowRadius, vPointShadowCoord[ i ], pointLightShadow.shadowCameraNear, pointLightShadow.shadowCameraFar ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SPOT_LIGHTS > 0 ) && defined( RE_Direct )
	SpotLight spotLight;
	vec4 spotColor;
	vec3 spotLightCoord;
	bool inSpotLightMap;
	#if defined( USE_SHADOWMAP ) && NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHTS; i ++ ) {
		spotLight = spotLights[ i ];
		getSpotLightInfo( spotLight, geometryPosition, directLight );
		#if ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#define SPOT_LIGHT_MAP_INDEX UNROLLED_LOOP_INDEX
		#elif ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		#define SPOT_LIGHT_MAP_INDEX NUM_SPOT_LIGHT_MAPS
		#else
		#define SPOT_LIGHT_MAP_INDEX ( UNROLLED_LOOP_INDEX - NUM_SPOT_LIGHT_SHADOWS + NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#endif
		#if ( SPOT_LIGHT_MAP_INDEX < NUM_SPOT_LIGHT_MAPS )
			spotLightCoord = vSpotLightCoord[ i ].xyz / vSpotLightCoord[ i ].w;
			inSpotLightMap = all( lessThan( abs( spotLightCoord * 2. - 1. ), vec3( 1.0 ) ) );
			spotColor = texture2D( spotLightMap[ SPOT_LIGHT_MAP_INDEX ], spotLightCoord.xy );
			directLight.color = inSpotLightMap ? directLight.color * spotColor.rgb : directLight.color;
		#endif
		#undef SPOT_LIGHT_MAP_INDEX
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		spotLightShadow = spotLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( spotShadowMap[ i ], spotLightShadow.shadowMapSize, spotLightShadow.shadowIntensity, spotLightShadow.shadowBias, spotLightShadow.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SUN_LIGHTS > 0 ) && defined( RE_Direct )
	SunLight sunLight;
	#if defined( USE_SHADOWMAP ) && NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHTS; i ++ ) {
		sunLight = sunLights[ i ];
		getSunLightInfo( sunLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SUN_LIGHT_SHADOWS )
		sunLightShadow = sunLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getSunShadow( sunShadowMap[ i ], sunLightShadow, UNROLLED_LOOP_INDEX ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_DIR_LIGHTS > 0 ) && defined( RE_Direct )
	DirectionalLight directionalLight;
	#if defined( USE_SHADOWMAP ) && NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHTS; i ++ ) {
		directionalLight = directionalLights[ i ];
		getDirectionalLightInfo( directionalLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_DIR_LIGHT_SHADOWS )
		directionalLightShadow = directionalLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( directionalShadowMap[ i ], directionalLightShadow.shadowMapSize, directionalLightShadow.shadowIntensity, directionalLightShadow.shadowBias, directionalLightShadow.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_RECT_AREA_LIGHTS > 0 ) && defined( RE_Direct_RectArea )
	RectAreaLight rectAreaLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_RECT_AREA_LIGHTS; i ++ ) {
		rectAreaLight = rectAreaLights[ i ];
		RE_Direct_RectArea( rectAreaLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if defined( RE_IndirectDiffuse )
	vec3 iblIrradiance = vec3( 0.0 );
	vec3 irradiance = getAmbientLightIrradiance( ambientLightColor );
	#if defined( USE_LIGHT_PROBES )
		irradiance += getLightProbeIrradiance( lightProbe, geometryNormal );
	#endif
	#if ( NUM_HEMI_LIGHTS > 0 )
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_HEMI_LIGHTS; i ++ ) {
			irradiance += getHemisphereLightIrradiance( hemisphereLights[ i ], geometryNormal );
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_LIGHT_PROBE_GRIDS > 0
		vec3 probeWorldPos = ( ( vec4( geometryPosition, 1.0 ) - viewMatrix[ 3 ] ) * viewMatrix ).xyz;
		vec3 probeWorldNormal = transformNormalByInverseViewMatrix( geometryNormal, viewMatrix );
		int probeGrid = - 1;
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( isInsideLightProbeGrid( probeWorldPos, probeWorldNormal, probesMin[ i ], probesMax[ i ], probesResolution[ i ] ) ) probeGrid = UNROLLED_LOOP_INDEX;
		}
		#pragma unroll_loop_end
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( probeGrid == UNROLLED_LOOP_INDEX ) irradiance += getLightProbeGridIrradiance( probesSH[ i ], probesMin[ i ], probesMax[ i ], probesResolution[ i ], probeWorldPos, probeWorldNormal );
		}
		#pragma unroll_loop_end
	#endif
#endif
#if defined( RE_IndirectSpecular )
	vec3 radiance = vec3( 0.0 );
	vec3 clearcoatRadiance = vec3( 0.0 );
#endif`,Ox=`#if defined( RE_IndirectDiffuse )
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		vec3 lightMapIrradiance = lightMapTexel.rgb * lightMapIntensity;
		irradiance += lightMapIrradiance;
	#endif
	#if defined( USE_ENVMAP ) && defined( ENVMAP_TYPE_PMREM )
		#if defined( STANDARD ) || defined( LAMBERT ) || defined( PHONG )
			iblIrradiance += getIBLIrradiance( geometryNormal );
		#endif
	#endif
#endif
#if defined( USE_ENVMAP ) && defined( RE_IndirectSpecular )
	#ifdef USE_ANISOTROPY
		vec3 iblRadiance = getIBLAnisotropyRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
	#else
		vec3 iblRadiance = getIBLRadiance( geometryViewDir, geometryNormal, material.roughness );
	#endif
	#ifdef USE_RETROREFLECTION
		#ifdef USE_ANISOTROPY
			vec3 retroIBLRadiance = getIBLAnisotropyRetroRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
		#else
			vec3 retroIBLRadiance = getIBLRetroRadiance( geometryViewDir, geometryNormal, material.roughness );
		#endif
		iblRadiance = mix( iblRadiance, retroIBLRadiance, saturate( material.retroreflectivity ) );
	#endif
	radiance += iblRadiance;
	#ifdef USE_CLEARCOAT
		clearcoatRadiance += getIBLRadiance( geometryViewDir, geometryClearcoatNormal, material.clearcoatRoughness );
	#endif
#endif`,Bx=`#if defined( RE_IndirectDiffuse )
	#if defined( LAMBERT ) || defined( PHONG )
		irradiance += iblIrradiance;
	#endif
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,kx=`#if NUM_LIGHT_PROBE_GRIDS > 0
uniform highp sampler3D probesSH[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMin[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMax[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesResolution[ NUM_LIGHT_PROBE_GRIDS ];
bool isInsideLightProbeGrid( vec3 worldPos, vec3 worldNormal, vec3 probesMin, vec3 probesMax, vec3 probesResolution ) {
	vec3 spacing = ( probesMax - probesMin ) / probesResolution;
	vec3 samplePos = worldPos + worldNormal * spacing * 0.5;
	vec3 margin = spacing * 0.01;
	return all( greaterThanEqual( samplePos, probesMin - margin ) ) && all( lessThanEqual( samplePos, probesMax + margin ) );
}
vec3 getLightProbeGridIrradiance( highp sampler3D probesSH, vec3 probesMin, vec3 probesMax, vec3 probesResolution, vec3 worldPos, vec3 worldNormal ) {
	vec3 res = probesResolution;
	vec3 gridRange = probesMax - probesMin;
	vec3 probeSpacing = gridRange / res;
	vec3 samplePos = worldPos + worldNormal * probeSpacing * 0.5;
	vec3 uvw = clamp( ( samplePos - probesMin ) / gridRange, 0.5 / res, 1.0 - 0.5 / res );
	float nz          = res.z;
	float paddedSlices = nz + 2.0;
	float atlasDepth  = 7.0 * paddedSlices;
	float uvZBase     = uvw.z * nz + 1.0;
	vec4 s0 = texture( probesSH, vec3( uvw.xy, ( uvZBase                       ) / atlasDepth ) );
	vec4 s1 = texture( probesSH, vec3( uvw.xy, ( uvZBase +       paddedSlices   ) / atlasDepth ) );
	vec4 s2 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 2.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s3 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 3.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s4 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 4.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s5 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 5.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s6 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 6.0 * paddedSlices   ) / atlasDepth ) );
	vec3 c0 = s0.xyz;
	vec3 c1 = vec3( s0.w, s1.xy );
	vec3 c2 = vec3( s1.zw, s2.x );
	vec3 c3 = s2.yzw;
	vec3 c4 = s3.xyz;
	vec3 c5 = vec3( s3.w, s4.xy );
	vec3 c6 = vec3( s4.zw, s5.x );
	vec3 c7 = s5.yzw;
	vec3 c8 = s6.xyz;
	float x = worldNormal.x, y = worldNormal.y, z = worldNormal.z;
	vec3 result = c0 * 0.886227;
	result += c1 * 2.0 * 0.511664 * y;
	result += c2 * 2.0 * 0.511664 * z;
	result += c3 * 2.0 * 0.511664 * x;
	result += c4 * 2.0 * 0.429043 * x * y;
	result += c5 * 2.0 * 0.429043 * y * z;
	result += c6 * ( 0.743125 * z * z - 0.247708 );
	result += c7 * 2.0 * 0.429043 * x * z;
	result += c8 * 0.429043 * ( x * x - y * y );
	return max( result, vec3( 0.0 ) );
}
#endif`,zx=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,Vx=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,Hx=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,Gx=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,Wx=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,$x=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,Xx=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
	#if defined( USE_POINTS_UV )
		vec2 uv = vUv;
	#else
		vec2 uv = ( uvTransform * vec3( gl_PointCoord.x, 1.0 - gl_PointCoord.y, 1 ) ).xy;
	#endif
#endif
#ifdef USE_MAP
	diffuseColor *= texture2D( map, uv );
#endif
#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, uv ).g;
#endif`,qx=`#if defined( USE_POINTS_UV )
	varying vec2 vUv;
#else
	#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
		uniform mat3 uvTransform;
	#endif
#endif
#ifdef USE_MAP
	uniform sampler2D map;
#endif
#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,Yx=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,Zx=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,Jx=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,Kx=`#if defined( USE_MORPHCOLORS )
	#if defined( USE_COLOR_ALPHA )
		vColor *= morphTargetBaseInfluence;
	#elif defined( USE_COLOR )
		vColor.rgb *= morphTargetBaseInfluence;
	#endif
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		#if defined( USE_COLOR_ALPHA )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor += getMorph( gl_VertexID, i, 2 ) * morphTargetInfluences[ i ];
		#elif defined( USE_COLOR )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor.rgb += getMorph( gl_VertexID, i, 2 ).rgb * morphTargetInfluences[ i ];
		#endif
	}
#endif`,jx=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,Qx=`#ifdef USE_MORPHTARGETS
	#ifndef USE_INSTANCING_MORPH
		uniform float morphTargetBaseInfluence;
		uniform float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	#endif
	uniform sampler2DArray morphTargetsTexture;
	uniform ivec2 morphTargetsTextureSize;
	vec4 getMorph( const in int vertexIndex, const in int morphTargetIndex, const in int offset ) {
		int texelIndex = vertexIndex * MORPHTARGETS_TEXTURE_STRIDE + offset;
		int y = texelIndex / morphTargetsTextureSize.x;
		int x = texelIndex - y * morphTargetsTextureSize.x;
		ivec3 morphUV = ivec3( x, y, morphTargetIndex );
		return texelFetch( morphTargetsTexture, morphUV, 0 );
	}
#endif`,ev=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,tv=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
#ifdef FLAT_SHADED
	vec3 fdx = dFdx( vViewPosition );
	vec3 fdy = dFdy( vViewPosition );
	vec3 normal = normalize( cross( fdx, fdy ) );
#else
	vec3 normal = normalize( vNormal );
	#ifdef DOUBLE_SIDED
		normal *= faceDirection;
	#endif
#endif
#if defined( USE_NORMALMAP_TANGENTSPACE ) || defined( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY )
	#ifdef USE_TANGENT
		mat3 tbn = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn = getTangentFrame( - vViewPosition, normal,
		#if defined( USE_NORMALMAP )
			vNormalMapUv
		#elif defined( USE_CLEARCOAT_NORMALMAP )
			vClearcoatNormalMapUv
		#else
			vUv
		#endif
		);
	#endif
	#ifdef DOUBLE_SIDED
		tbn[0] *= faceDirection;
		tbn[1] *= faceDirection;
	#endif
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	#ifdef USE_TANGENT
		mat3 tbn2 = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn2 = getTangentFrame( - vViewPosition, normal, vClearcoatNormalMapUv );
	#endif
	#ifdef DOUBLE_SIDED
		tbn2[0] *= faceDirection;
		tbn2[1] *= faceDirection;
	#endif
#endif
vec3 nonPerturbedNormal = normal;`,nv=`#ifdef USE_NORMALMAP_OBJECTSPACE
	normal = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#ifdef FLIP_SIDED
		normal = - normal;
	#endif
	#ifdef DOUBLE_SIDED
		normal = normal * faceDirection;
	#endif
	normal = normalize( normalMatrix * normal );
#elif defined( USE_NORMALMAP_TANGENTSPACE )
	vec3 mapN = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#if defined( USE_PACKED_NORMALMAP )
		mapN = vec3( mapN.xy, sqrt( saturate( 1.0 - dot( mapN.xy, mapN.xy ) ) ) );
	#endif
	mapN.xy *= normalScale;
	normal = normalize( tbn * mapN );
#elif defined( USE_BUMPMAP )
	normal = perturbNormalArb( - vViewPosition, normal, dHdxy_fwd(), faceDirection );
#endif`,iv=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,sv=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,rv=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
		#ifdef FLIP_SIDED
			vBitangent = - vBitangent;
		#endif
	#endif
#endif`,ov=`#ifdef USE_NORMALMAP
	uniform sampler2D normalMap;
	uniform vec2 normalScale;
#endif
#ifdef USE_NORMALMAP_OBJECTSPACE
	uniform mat3 normalMatrix;
#endif
#if ! defined ( USE_TANGENT ) && ( defined ( USE_NORMALMAP_TANGENTSPACE ) || defined ( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY ) )
	mat3 getTangentFrame( vec3 eye_pos, vec3 surf_norm, vec2 uv ) {
		vec3 q0 = dFdx( eye_pos.xyz );
		vec3 q1 = dFdy( eye_pos.xyz );
		vec2 st0 = dFdx( uv.st );
		vec2 st1 = dFdy( uv.st );
		vec3 N = surf_norm;
		vec3 q1perp = cross( q1, N );
		vec3 q0perp = cross( N, q0 );
		vec3 T = q1perp * st0.x + q0perp * st1.x;
		vec3 B = q1perp * st0.y + q0perp * st1.y;
		float det = max( dot( T, T ), dot( B, B ) );
		float scale = ( det == 0.0 ) ? 0.0 : inversesqrt( det );
		return mat3( T * scale, B * scale, N );
	}
#endif`,av=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,lv=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,cv=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,hv=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,uv=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,dv=`vec3 packNormalToRGB( const in vec3 normal ) {
	return normalize( normal ) * 0.5 + 0.5;
}
vec3 unpackRGBToNormal( const in vec3 rgb ) {
	return 2.0 * rgb.xyz - 1.0;
}
const float PackUpscale = 256. / 255.;const float UnpackDownscale = 255. / 256.;const float ShiftRight8 = 1. / 256.;
const float Inv255 = 1. / 255.;
const vec4 PackFactors = vec4( 1.0, 256.0, 256.0 * 256.0, 256.0 * 256.0 * 256.0 );
const vec2 UnpackFactors2 = vec2( UnpackDownscale, 1.0 / PackFactors.g );
const vec3 UnpackFactors3 = vec3( UnpackDownscale / PackFactors.rg, 1.0 / PackFactors.b );
const vec4 UnpackFactors4 = vec4( UnpackDownscale / PackFactors.rgb, 1.0 / PackFactors.a );
vec4 packDepthToRGBA( const in float v ) {
	if( v <= 0.0 )
		return vec4( 0., 0., 0., 0. );
	if( v >= 1.0 )
		return vec4( 1., 1., 1., 1. );
	float vuf;
	float af = modf( v * PackFactors.a, vuf );
	float bf = modf( vuf * ShiftRight8, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec4( vuf * Inv255, gf * PackUpscale, bf * PackUpscale, af );
}
vec3 packDepthToRGB( const in float v ) {
	if( v <= 0.0 )
		return vec3( 0., 0., 0. );
	if( v >= 1.0 )
		return vec3( 1., 1., 1. );
	float vuf;
	float bf = modf( v * PackFactors.b, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec3( vuf * Inv255, gf * PackUpscale, bf );
}
vec2 packDepthToRG( const in float v ) {
	if( v <= 0.0 )
		return vec2( 0., 0. );
	if( v >= 1.0 )
		return vec2( 1., 1. );
	float vuf;
	float gf = modf( v * 256., vuf );
	return vec2( vuf * Inv255, gf );
}
float unpackRGBAToDepth( const in vec4 v ) {
	return dot( v, UnpackFactors4 );
}
float unpackRGBToDepth( const in vec3 v ) {
	return dot( v, UnpackFactors3 );
}
float unpackRGToDepth( const in vec2 v ) {
	return v.r * UnpackFactors2.r + v.g * UnpackFactors2.g;
}
vec4 pack2HalfToRGBA( const in vec2 v ) {
	vec4 r = vec4( v.x, fract( v.x * 255.0 ), v.y, fract( v.y * 255.0 ) );
	return vec4( r.x - r.y / 255.0, r.y, r.z - r.w / 255.0, r.w );
}
vec2 unpackRGBATo2Half( const in vec4 v ) {
	return vec2( v.x + ( v.y / 255.0 ), v.z + ( v.w / 255.0 ) );
}
float viewZToOrthographicDepth( const in float viewZ, const in float near, const in float far ) {
	return ( viewZ + near ) / ( near - far );
}
float orthographicDepthToViewZ( const in float depth, const in float near, const in float far ) {
	#ifdef USE_REVERSED_DEPTH_BUFFER
	
		return depth * ( far - near ) - far;
	#else
		return depth * ( near - far ) - near;
	#endif
}
float viewZToPerspectiveDepth( const in float viewZ, const in float near, const in float far ) {
	return ( ( near + viewZ ) * far ) / ( ( far - near ) * viewZ );
}
float perspectiveDepthToViewZ( const in float depth, const in float near, const in float far ) {
	
	#ifdef USE_REVERSED_DEPTH_BUFFER
		return ( near * far ) / ( ( near - far ) * depth - near );
	#else
		return ( near * far ) / ( ( far - near ) * depth - far );
	#endif
}`,fv=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,pv=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,mv=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,gv=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,_v=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,xv=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,vv=`#if NUM_SPOT_LIGHT_COORDS > 0
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#if NUM_SPOT_LIGHT_MAPS > 0
	uniform sampler2D spotLightMap[ NUM_SPOT_LIGHT_MAPS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		#define SUN_LIGHT_CASCADES 2
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#else
			uniform sampler2D sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#endif
		uniform mat4 sunShadowMatrix[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		uniform vec4 sunShadowCascade[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
		struct SunLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SunLightShadow sunLightShadows[ NUM_SUN_LIGHT_SHADOWS ];
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#else
			uniform sampler2D directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#endif
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#else
			uniform sampler2D spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#endif
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform samplerCubeShadow pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#elif defined( SHADOWMAP_TYPE_BASIC )
			uniform samplerCube pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#endif
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float interleavedGradientNoise( vec2 position ) {
			return fract( 52.9829189 * fract( dot( position, vec2( 0.06711056, 0.00583715 ) ) ) );
		}
		vec2 vogelDiskSample( int sampleIndex, int samplesCount, float phi ) {
			const float goldenAngle = 2.399963229728653;
			float r = sqrt( ( float( sampleIndex ) + 0.5 ) / float( samplesCount ) );
			float theta = float( sampleIndex ) * goldenAngle + phi;
			return vec2( cos( theta ), sin( theta ) ) * r;
		}
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float getShadow( sampler2DShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 texelSize = vec2( 1.0 ) / shadowMapSize;
				vec2 radius = shadowRadius * texelSize;
				float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
				shadow = (
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 0, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 1, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 2, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 3, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 4, 5, phi ) * radius, shadowCoord.z ) )
				) * 0.2;
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#elif defined( SHADOWMAP_TYPE_VSM )
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 distribution = texture2D( shadowMap, shadowCoord.xy ).rg;
				float mean = distribution.x;
				float variance = distribution.y * distribution.y;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					float hard_shadow = step( mean, shadowCoord.z );
				#else
					float hard_shadow = step( shadowCoord.z, mean );
				#endif
				
				if ( hard_shadow == 1.0 ) {
					shadow = 1.0;
				} else {
					variance = max( variance, 0.0000001 );
					float d = shadowCoord.z - mean;
					float p_max = variance / ( variance + d * d );
					p_max = clamp( ( p_max - 0.3 ) / 0.65, 0.0, 1.0 );
					shadow = max( hard_shadow, p_max );
				}
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#else
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				float depth = texture2D( shadowMap, shadowCoord.xy ).r;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					shadow = step( depth, shadowCoord.z );
				#else
					shadow = step( shadowCoord.z, depth );
				#endif
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#endif
	#if NUM_SUN_LIGHT_SHADOWS > 0
		float getSunShadow(
			#if defined( SHADOWMAP_TYPE_PCF )
				sampler2DShadow shadowMap,
			#else
				sampler2D shadowMap,
			#endif
			SunLightShadow sunLightShadow,
			int shadowIndex
		) {
			vec4 shadowWorldPosition = vec4( vSunShadowWorldPosition.xyz + vSunShadowWorldNormal * sunLightShadow.shadowNormalBias, 1.0 );
			float viewDepth = vSunShadowWorldPosition.w;
			int cascadeOffset = shadowIndex * SUN_LIGHT_CASCADES;
			float shadow = 1.0;
			for ( int i = SUN_LIGHT_CASCADES - 1; i >= 0; i -- ) {
				vec4 cascade = sunShadowCascade[ cascadeOffset + i ];
				if ( viewDepth >= cascade.x && viewDepth < cascade.y ) {
					float cascadeShadow = getShadow(
						shadowMap,
						sunLightShadow.shadowMapSize,
						sunLightShadow.shadowIntensity,
						sunLightShadow.shadowBias,
						sunLightShadow.shadowRadius,
						sunShadowMatrix[ cascadeOffset + i ] * shadowWorldPosition
					);
					shadow = mix( cascadeShadow, shadow, smoothstep( cascade.z, cascade.y, viewDepth ) );
				}
			}
			return shadow;
		}
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
	#if defined( SHADOWMAP_TYPE_PCF )
	float getPointShadow( samplerCubeShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 bd3D = normalize( lightToPosition );
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float lightDistance = length( lightToPosition );
			float depthRange = shadowCameraFar - shadowCameraNear;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				float depthA = - shadowCameraNear / depthRange - shadowBias;
				float depthB = shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#else
				float depthA = shadowCameraFar / depthRange + shadowBias;
				float depthB = - shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#endif
			float texelSize = shadowRadius / shadowMapSize.x;
			vec3 absDir = abs( bd3D );
			vec3 tangent = absDir.x > absDir.z ? vec3( 0.0, 1.0, 0.0 ) : vec3( 1.0, 0.0, 0.0 );
			tangent = normalize( cross( bd3D, tangent ) );
			vec3 bitangent = cross( bd3D, tangent );
			float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
			shadow = 0.0;
			for ( int i = 0; i < 5; i ++ ) {
				vec2 offset = vogelDiskSample( i, 5, phi );
				vec3 direction = bd3D + ( tangent * offset.x + bitangent * offset.y ) * texelSize;
				vec3 absDirection = abs( direction );
				float dp = depthA + depthB / max( max( absDirection.x, absDirection.y ), absDirection.z );
				shadow += texture( shadowMap, vec4( direction, dp ) );
			}
			shadow *= 0.2;
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#elif defined( SHADOWMAP_TYPE_BASIC )
	float getPointShadow( samplerCube shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float dp = ( shadowCameraFar * ( viewSpaceZ - shadowCameraNear ) ) / ( viewSpaceZ * ( shadowCameraFar - shadowCameraNear ) );
			dp += shadowBias;
			vec3 bd3D = normalize( lightToPosition );
			float depth = textureCube( shadowMap, bd3D ).r;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				depth = 1.0 - depth;
			#endif
			shadow = step( dp, depth );
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#endif
	#endif
#endif`,yv=`#if NUM_SPOT_LIGHT_COORDS > 0
	uniform mat4 spotLightMatrix[ NUM_SPOT_LIGHT_COORDS ];
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		uniform mat4 directionalShadowMatrix[ NUM_DIR_LIGHT_SHADOWS ];
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		uniform mat4 pointShadowMatrix[ NUM_POINT_LIGHT_SHADOWS ];
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
#endif`,bv=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_SUN_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
	#ifdef HAS_NORMAL
		vec3 shadowWorldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
	#else
		vec3 shadowWorldNormal = vec3( 0.0 );
	#endif
	vec4 shadowWorldPosition;
#endif
#if defined( USE_SHADOWMAP )
	#if NUM_SUN_LIGHT_SHADOWS > 0
		vSunShadowWorldPosition = vec4( worldPosition.xyz, - mvPosition.z );
		vSunShadowWorldNormal = shadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * directionalLightShadows[ i ].shadowNormalBias, 0 );
			vDirectionalShadowCoord[ i ] = directionalShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * pointLightShadows[ i ].shadowNormalBias, 0 );
			vPointShadowCoord[ i ] = pointShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
#endif
#if NUM_SPOT_LIGHT_COORDS > 0
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_COORDS; i ++ ) {
		shadowWorldPosition = worldPosition;
		#if ( defined( USE_SHADOWMAP ) && UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
			shadowWorldPosition.xyz += shadowWorldNormal * spotLightShadows[ i ].shadowNormalBias;
		#endif
		vSpotLightCoord[ i ] = spotLightMatrix[ i ] * shadowWorldPosition;
	}
	#pragma unroll_loop_end
#endif`,Sv=`float getShadowMask() {
	float shadow = 1.0;
	#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHT_SHADOWS; i ++ ) {
		sunLight = sunLightShadows[ i ];
		shadow *= receiveShadow ? getSunShadow( sunShadowMap[ i ], sunLight, UNROLLED_LOOP_INDEX ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
		directionalLight = directionalLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( directionalShadowMap[ i ], directionalLight.shadowMapSize, directionalLight.shadowIntensity, directionalLight.shadowBias, directionalLight.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_SHADOWS; i ++ ) {
		spotLight = spotLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( spotShadowMap[ i ], spotLight.shadowMapSize, spotLight.shadowIntensity, spotLight.shadowBias, spotLight.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0 && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
	PointLightShadow pointLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
		pointLight = pointLightShadows[ i ];
		shadow *= receiveShadow ? getPointShadow( pointShadowMap[ i ], pointLight.shadowMapSize, pointLight.shadowIntensity, pointLight.shadowBias, pointLight.shadowRadius, vPointShadowCoord[ i ], pointLight.shadowCameraNear, pointLight.shadowCameraFar ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#endif
	return shadow;
}`,Mv=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,wv=`#ifdef USE_SKINNING
	uniform mat4 bindMatrix;
	uniform mat4 bindMatrixInverse;
	uniform highp sampler2D boneTexture;
	mat4 getBoneMatrix( const in float i ) {
		int size = textureSize( boneTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( boneTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( boneTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( boneTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( boneTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
#endif`,Ev=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,Tv=`#ifdef USE_SKINNING
	mat4 skinMatrix = mat4( 0.0 );
	skinMatrix += skinWeight.x * boneMatX;
	skinMatrix += skinWeight.y * boneMatY;
	skinMatrix += skinWeight.z * boneMatZ;
	skinMatrix += skinWeight.w * boneMatW;
	skinMatrix = bindMatrixInverse * skinMatrix * bindMatrix;
	objectNormal = vec4( skinMatrix * vec4( objectNormal, 0.0 ) ).xyz;
	#ifdef USE_TANGENT
		objectTangent = vec4( skinMatrix * vec4( objectTangent, 0.0 ) ).xyz;
	#endif
#endif`,Av=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,Rv=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,Cv=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,Pv=`#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
uniform float toneMappingExposure;
vec3 LinearToneMapping( vec3 color ) {
	return saturate( toneMappingExposure * color );
}
vec3 ReinhardToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	return saturate( color / ( vec3( 1.0 ) + color ) );
}
vec3 CineonToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	color = max( vec3( 0.0 ), color - 0.004 );
	return pow( ( color * ( 6.2 * color + 0.5 ) ) / ( color * ( 6.2 * color + 1.7 ) + 0.06 ), vec3( 2.2 ) );
}
vec3 RRTAndODTFit( vec3 v ) {
	vec3 a = v * ( v + 0.0245786 ) - 0.000090537;
	vec3 b = v * ( 0.983729 * v + 0.4329510 ) + 0.238081;
	return a / b;
}
vec3 ACESFilmicToneMapping( vec3 color ) {
	const mat3 ACESInputMat = mat3(
		vec3( 0.59719, 0.07600, 0.02840 ),		vec3( 0.35458, 0.90834, 0.13383 ),
		vec3( 0.04823, 0.01566, 0.83777 )
	);
	const mat3 ACESOutputMat = mat3(
		vec3(  1.60475, -0.10208, -0.00327 ),		vec3( -0.53108,  1.10813, -0.07276 ),
		vec3( -0.07367, -0.00605,  1.07602 )
	);
	color *= toneMappingExposure / 0.6;
	color = ACESInputMat * color;
	color = RRTAndODTFit( color );
	color = ACESOutputMat * color;
	return saturate( color );
}
const mat3 LINEAR_REC2020_TO_LINEAR_SRGB = mat3(
	vec3( 1.6605, - 0.1246, - 0.0182 ),
	vec3( - 0.5876, 1.1329, - 0.1006 ),
	vec3( - 0.0728, - 0.0083, 1.1187 )
);
const mat3 LINEAR_SRGB_TO_LINEAR_REC2020 = mat3(
	vec3( 0.6274, 0.0691, 0.0164 ),
	vec3( 0.3293, 0.9195, 0.0880 ),
	vec3( 0.0433, 0.0113, 0.8956 )
);
vec3 agxDefaultContrastApprox( vec3 x ) {
	vec3 x2 = x * x;
	vec3 x4 = x2 * x2;
	return + 15.5 * x4 * x2
		- 40.14 * x4 * x
		+ 31.96 * x4
		- 6.868 * x2 * x
		+ 0.4298 * x2
		+ 0.1191 * x
		- 0.00232;
}
vec3 AgXToneMapping( vec3 color ) {
	const mat3 AgXInsetMatrix = mat3(
		vec3( 0.856627153315983, 0.137318972929847, 0.11189821299995 ),
		vec3( 0.0951212405381588, 0.761241990602591, 0.0767994186031903 ),
		vec3( 0.0482516061458583, 0.101439036467562, 0.811302368396859 )
	);
	const mat3 AgXOutsetMatrix = mat3(
		vec3( 1.1271005818144368, - 0.1413297634984383, - 0.14132976349843826 ),
		vec3( - 0.11060664309660323, 1.157823702216272, - 0.11060664309660294 ),
		vec3( - 0.016493938717834573, - 0.016493938717834257, 1.2519364065950405 )
	);
	const float AgxMinEv = - 12.47393;	const float AgxMaxEv = 4.026069;
	color *= toneMappingExposure;
	color = LINEAR_SRGB_TO_LINEAR_REC2020 * color;
	color = AgXInsetMatrix * color;
	color = max( color, 1e-10 );	color = log2( color );
	color = ( color - AgxMinEv ) / ( AgxMaxEv - AgxMinEv );
	color = clamp( color, 0.0, 1.0 );
	color = agxDefaultContrastApprox( color );
	color = AgXOutsetMatrix * color;
	color = pow( max( vec3( 0.0 ), color ), vec3( 2.2 ) );
	color = LINEAR_REC2020_TO_LINEAR_SRGB * color;
	color = clamp( color, 0.0, 1.0 );
	return color;
}
vec3 NeutralToneMapping( vec3 color ) {
	const float StartCompression = 0.8 - 0.04;
	const float Desaturation = 0.15;
	color *= toneMappingExposure;
	float x = min( color.r, min( color.g, color.b ) );
	float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
	color -= offset;
	float peak = max( color.r, max( color.g, color.b ) );
	if ( peak < StartCompression ) return color;
	float d = 1. - StartCompression;
	float newPeak = 1. - d * d / ( peak + d - StartCompression );
	color *= newPeak / peak;
	float g = 1. - 1. / ( Desaturation * ( peak - newPeak ) + 1. );
	return mix( color, vec3( newPeak ), g );
}
vec3 CustomToneMapping( vec3 color ) { return color; }`,Iv=`#ifdef USE_TRANSMISSION
	material.transmission = transmission;
	material.transmissionAlpha = 1.0;
	material.thickness = thickness;
	material.attenuationDistance = attenuationDistance;
	material.attenuationColor = attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		material.transmission *= texture2D( transmissionMap, vTransmissionMapUv ).r;
	#endif
	#ifdef USE_THICKNESSMAP
		material.thickness *= texture2D( thicknessMap, vThicknessMapUv ).g;
	#endif
	vec3 pos = vWorldPosition;
	vec3 v = normalize( cameraPosition - pos );
	vec3 n = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec4 transmitted = getIBLVolumeRefraction(
		n, v, material.roughness, material.diffuseContribution, material.specularColorBlended, material.specularF90,
		pos, modelMatrix, viewMatrix, projectionMatrix, material.dispersion, material.ior, material.thickness,
		material.attenuationColor, material.attenuationDistance );
	material.transmissionAlpha = mix( material.transmissionAlpha, transmitted.a, material.transmission );
	totalDiffuse = mix( totalDiffuse, transmitted.rgb, material.transmission );
#endif`,Lv=`#ifdef USE_TRANSMISSION
	uniform float transmission;
	uniform float thickness;
	uniform float attenuationDistance;
	uniform vec3 attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		uniform sampler2D transmissionMap;
	#endif
	#ifdef USE_THICKNESSMAP
		uniform sampler2D thicknessMap;
	#endif
	uniform vec2 transmissionSamplerSize;
	uniform sampler2D transmissionSamplerMap;
	uniform mat4 modelMatrix;
	uniform mat4 projectionMatrix;
	varying vec3 vWorldPosition;
	float w0( float a ) {
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - a + 3.0 ) - 3.0 ) + 1.0 );
	}
	float w1( float a ) {
		return ( 1.0 / 6.0 ) * ( a *  a * ( 3.0 * a - 6.0 ) + 4.0 );
	}
	float w2( float a ){
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - 3.0 * a + 3.0 ) + 3.0 ) + 1.0 );
	}
	float w3( float a ) {
		return ( 1.0 / 6.0 ) * ( a * a * a );
	}
	float g0( float a ) {
		return w0( a ) + w1( a );
	}
	float g1( float a ) {
		return w2( a ) + w3( a );
	}
	float h0( float a ) {
		return - 1.0 + w1( a ) / ( w0( a ) + w1( a ) );
	}
	float h1( float a ) {
		return 1.0 + w3( a ) / ( w2( a ) + w3( a ) );
	}
	vec4 bicubic( sampler2D tex, vec2 uv, vec4 texelSize, float lod ) {
		uv = uv * texelSize.zw + 0.5;
		vec2 iuv = floor( uv );
		vec2 fuv = fract( uv );
		float g0x = g0( fuv.x );
		float g1x = g1( fuv.x );
		float h0x = h0( fuv.x );
		float h1x = h1( fuv.x );
		float h0y = h0( fuv.y );
		float h1y = h1( fuv.y );
		vec2 p0 = ( vec2( iuv.x + h0x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p1 = ( vec2( iuv.x + h1x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p2 = ( vec2( iuv.x + h0x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		vec2 p3 = ( vec2( iuv.x + h1x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		return g0( fuv.y ) * ( g0x * textureLod( tex, p0, lod ) + g1x * textureLod( tex, p1, lod ) ) +
			g1( fuv.y ) * ( g0x * textureLod( tex, p2, lod ) + g1x * textureLod( tex, p3, lod ) );
	}
	vec4 textureBicubic( sampler2D sampler, vec2 uv, float lod ) {
		vec2 fLodSize = vec2( textureSize( sampler, int( lod ) ) );
		vec2 cLodSize = vec2( textureSize( sampler, int( lod + 1.0 ) ) );
		vec2 fLodSizeInv = 1.0 / fLodSize;
		vec2 cLodSizeInv = 1.0 / cLodSize;
		vec4 fSample = bicubic( sampler, uv, vec4( fLodSizeInv, fLodSize ), floor( lod ) );
		vec4 cSample = bicubic( sampler, uv, vec4( cLodSizeInv, cLodSize ), ceil( lod ) );
		return mix( fSample, cSample, fract( lod ) );
	}
	vec3 getVolumeTransmissionRay( const in vec3 n, const in vec3 v, const in float thickness, const in float ior, const in mat4 modelMatrix ) {
		vec3 refractionVector = refract( - v, normalize( n ), 1.0 / ior );
		vec3 modelScale;
		modelScale.x = length( vec3( modelMatrix[ 0 ].xyz ) );
		modelScale.y = length( vec3( modelMatrix[ 1 ].xyz ) );
		modelScale.z = length( vec3( modelMatrix[ 2 ].xyz ) );
		return normalize( refractionVector ) * thickness * modelScale;
	}
	float applyIorToRoughness( const in float roughness, const in float ior ) {
		return roughness * clamp( ior * 2.0 - 2.0, 0.0, 1.0 );
	}
	vec4 getTransmissionSample( const in vec2 fragCoord, const in float roughness, const in float ior ) {
		float lod = log2( transmissionSamplerSize.x ) * applyIorToRoughness( roughness, ior );
		return textureBicubic( transmissionSamplerMap, fragCoord.xy, lod );
	}
	vec3 volumeAttenuation( const in float transmissionDistance, const in vec3 attenuationColor, const in float attenuationDistance ) {
		if ( isinf( attenuationDistance ) ) {
			return vec3( 1.0 );
		} else {
			vec3 attenuationCoefficient = -log( attenuationColor ) / attenuationDistance;
			vec3 transmittance = exp( - attenuationCoefficient * transmissionDistance );			return transmittance;
		}
	}
	vec4 getIBLVolumeRefraction( const in vec3 n, const in vec3 v, const in float roughness, const in vec3 diffuseColor,
		const in vec3 specularColor, const in float specularF90, const in vec3 position, const in mat4 modelMatrix,
		const in mat4 viewMatrix, const in mat4 projMatrix, const in float dispersion, const in float ior, const in float thickness,
		const in vec3 attenuationColor, const in float attenuationDistance ) {
		vec4 transmittedLight;
		vec3 transmittance;
		#ifdef USE_DISPERSION
			float halfSpread = ( ior - 1.0 ) * 0.025 * dispersion;
			vec3 iors = vec3( ior - halfSpread, ior, ior + halfSpread );
			for ( int i = 0; i < 3; i ++ ) {
				vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, iors[ i ], modelMatrix );
				vec3 refractedRayExit = position + transmissionRay;
				vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
				vec2 refractionCoords = ndcPos.xy / ndcPos.w;
				refractionCoords += 1.0;
				refractionCoords /= 2.0;
				vec4 transmissionSample = getTransmissionSample( refractionCoords, roughness, iors[ i ] );
				transmittedLight[ i ] = transmissionSample[ i ];
				transmittedLight.a += transmissionSample.a;
				transmittance[ i ] = diffuseColor[ i ] * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance )[ i ];
			}
			transmittedLight.a /= 3.0;
		#else
			vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, ior, modelMatrix );
			vec3 refractedRayExit = position + transmissionRay;
			vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
			vec2 refractionCoords = ndcPos.xy / ndcPos.w;
			refractionCoords += 1.0;
			refractionCoords /= 2.0;
			transmittedLight = getTransmissionSample( refractionCoords, roughness, ior );
			transmittance = diffuseColor * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance );
		#endif
		vec3 attenuatedColor = transmittance * transmittedLight.rgb;
		vec3 F = EnvironmentBRDF( n, v, specularColor, specularF90, roughness );
		float transmittanceFactor = ( transmittance.r + transmittance.g + transmittance.b ) / 3.0;
		return vec4( ( 1.0 - F ) * attenuatedColor, 1.0 - ( 1.0 - transmittedLight.a ) * transmittanceFactor );
	}
#endif`,Dv=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_SPECULARMAP
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,Nv=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	uniform mat3 mapTransform;
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	uniform mat3 alphaMapTransform;
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	uniform mat3 lightMapTransform;
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	uniform mat3 aoMapTransform;
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	uniform mat3 bumpMapTransform;
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	uniform mat3 normalMapTransform;
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_DISPLACEMENTMAP
	uniform mat3 displacementMapTransform;
	varying vec2 vDisplacementMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	uniform mat3 emissiveMapTransform;
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	uniform mat3 metalnessMapTransform;
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	uniform mat3 roughnessMapTransform;
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	uniform mat3 diffuseRoughnessMapTransform;
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	uniform mat3 anisotropyMapTransform;
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	uniform mat3 clearcoatMapTransform;
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform mat3 clearcoatNormalMapTransform;
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform mat3 clearcoatRoughnessMapTransform;
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	uniform mat3 sheenColorMapTransform;
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	uniform mat3 sheenRoughnessMapTransform;
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	uniform mat3 iridescenceMapTransform;
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform mat3 iridescenceThicknessMapTransform;
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SPECULARMAP
	uniform mat3 specularMapTransform;
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	uniform mat3 specularColorMapTransform;
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	uniform mat3 specularIntensityMapTransform;
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,Uv=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	vUv = vec3( uv, 1 ).xy;
#endif
#ifdef USE_MAP
	vMapUv = ( mapTransform * vec3( MAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ALPHAMAP
	vAlphaMapUv = ( alphaMapTransform * vec3( ALPHAMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_LIGHTMAP
	vLightMapUv = ( lightMapTransform * vec3( LIGHTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_AOMAP
	vAoMapUv = ( aoMapTransform * vec3( AOMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_BUMPMAP
	vBumpMapUv = ( bumpMapTransform * vec3( BUMPMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_NORMALMAP
	vNormalMapUv = ( normalMapTransform * vec3( NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DISPLACEMENTMAP
	vDisplacementMapUv = ( displacementMapTransform * vec3( DISPLACEMENTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_EMISSIVEMAP
	vEmissiveMapUv = ( emissiveMapTransform * vec3( EMISSIVEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_METALNESSMAP
	vMetalnessMapUv = ( metalnessMapTransform * vec3( METALNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ROUGHNESSMAP
	vRoughnessMapUv = ( roughnessMapTransform * vec3( ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	vDiffuseRoughnessMapUv = ( diffuseRoughnessMapTransform * vec3( DIFFUSE_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ANISOTROPYMAP
	vAnisotropyMapUv = ( anisotropyMapTransform * vec3( ANISOTROPYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOATMAP
	vClearcoatMapUv = ( clearcoatMapTransform * vec3( CLEARCOATMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	vClearcoatNormalMapUv = ( clearcoatNormalMapTransform * vec3( CLEARCOAT_NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	vClearcoatRoughnessMapUv = ( clearcoatRoughnessMapTransform * vec3( CLEARCOAT_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCEMAP
	vIridescenceMapUv = ( iridescenceMapTransform * vec3( IRIDESCENCEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	vIridescenceThicknessMapUv = ( iridescenceThicknessMapTransform * vec3( IRIDESCENCE_THICKNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_COLORMAP
	vSheenColorMapUv = ( sheenColorMapTransform * vec3( SHEEN_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	vSheenRoughnessMapUv = ( sheenRoughnessMapTransform * vec3( SHEEN_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULARMAP
	vSpecularMapUv = ( specularMapTransform * vec3( SPECULARMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_COLORMAP
	vSpecularColorMapUv = ( specularColorMapTransform * vec3( SPECULAR_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	vSpecularIntensityMapUv = ( specularIntensityMapTransform * vec3( SPECULAR_INTENSITYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_TRANSMISSIONMAP
	vTransmissionMapUv = ( transmissionMapTransform * vec3( TRANSMISSIONMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_THICKNESSMAP
	vThicknessMapUv = ( thicknessMapTransform * vec3( THICKNESSMAP_UV, 1 ) ).xy;
#endif`,Fv=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`,Ov=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,Bv=`uniform sampler2D t2D;
uniform float backgroundIntensity;
varying vec2 vUv;
void main() {
	vec4 texColor = texture2D( t2D, vUv );
	#ifdef DECODE_VIDEO_TEXTURE
		texColor = vec4( mix( pow( texColor.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), texColor.rgb * 0.0773993808, vec3( lessThanEqual( texColor.rgb, vec3( 0.04045 ) ) ) ), texColor.w );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,kv=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,zv=`uniform float backgroundBlurriness;
uniform float backgroundIntensity;
uniform mat3 backgroundRotation;
varying vec3 vWorldDirection;
#include <envmap_common_pars_fragment>
void main() {
	#ifdef ENVMAP_TYPE_PMREM
		vec4 texColor = textureLod( envMap, backgroundRotation * vWorldDirection, roughnessToMip( backgroundBlurriness ) );
	#else
		vec4 texColor = textureCube( envMap, backgroundRotation * vWorldDirection );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Vv=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,Hv=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Gv=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
varying vec2 vHighPrecisionZW;
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vHighPrecisionZW = gl_Position.zw;
}`,Wv=`#if DEPTH_PACKING == 3200
	uniform float opacity;
#endif
#include <common>
#include <packing>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
varying vec2 vHighPrecisionZW;
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#if DEPTH_PACKING == 3200
		diffuseColor.a = opacity;
	#endif
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <logdepthbuf_fragment>
	#ifdef USE_REVERSED_DEPTH_BUFFER
		float fragCoordZ = vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ];
	#else
		float fragCoordZ = 0.5 * vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ] + 0.5;
	#endif
	#if DEPTH_PACKING == 3200
		gl_FragColor = vec4( vec3( 1.0 - fragCoordZ ), opacity );
	#elif DEPTH_PACKING == 3201
		gl_FragColor = packDepthToRGBA( fragCoordZ );
	#elif DEPTH_PACKING == 3202
		gl_FragColor = vec4( packDepthToRGB( fragCoordZ ), 1.0 );
	#elif DEPTH_PACKING == 3203
		gl_FragColor = vec4( packDepthToRG( fragCoordZ ), 0.0, 1.0 );
	#endif
}`,$v=`#define DISTANCE
varying vec3 vWorldPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <worldpos_vertex>
	#include <clipping_planes_vertex>
	vWorldPosition = worldPosition.xyz;
}`,Xv=`#define DISTANCE
uniform vec3 referencePosition;
uniform float nearDistance;
uniform float farDistance;
varying vec3 vWorldPosition;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	float dist = length( vWorldPosition - referencePosition );
	dist = ( dist - nearDistance ) / ( farDistance - nearDistance );
	dist = saturate( dist );
	gl_FragColor = vec4( dist, 0.0, 0.0, 1.0 );
}`,qv=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,Yv=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,Zv=`uniform float scale;
attribute float lineDistance;
varying float vLineDistance;
#include <common>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	vLineDistance = scale * lineDistance;
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,Jv=`uniform vec3 diffuse;
uniform float opacity;
uniform float dashSize;
uniform float totalSize;
varying float vLineDistance;
#include <common>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	if ( mod( vLineDistance, totalSize ) > dashSize ) {
		discard;
	}
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,Kv=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#if defined ( USE_ENVMAP ) || defined ( USE_SKINNING )
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinbase_vertex>
		#include <skinnormal_vertex>
		#include <defaultnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <fog_vertex>
}`,jv=`uniform vec3 diffuse;
uniform float opacity;
#ifndef FLAT_SHADED
	varying vec3 vNormal;
#endif
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		reflectedLight.indirectDiffuse += lightMapTexel.rgb * lightMapIntensity * RECIPROCAL_PI;
	#else
		reflectedLight.indirectDiffuse += vec3( 1.0 );
	#endif
	#include <aomap_fragment>
	reflectedLight.indirectDiffuse *= diffuseColor.rgb;
	vec3 outgoingLight = reflectedLight.indirectDiffuse;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,Qv=`#define LAMBERT
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,ey=`#define LAMBERT
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_lambert_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_lambert_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,ty=`#define MATCAP
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <displacementmap_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
	vViewPosition = - mvPosition.xyz;
}`,ny=`#define MATCAP
uniform vec3 diffuse;
uniform float opacity;
uniform sampler2D matcap;
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	vec3 viewDir = normalize( vViewPosition );
	vec3 x = normalize( vec3( viewDir.z, 0.0, - viewDir.x ) );
	vec3 y = cross( viewDir, x );
	vec2 uv = vec2( dot( x, normal ), dot( y, normal ) ) * 0.495 + 0.5;
	#ifdef USE_MATCAP
		vec4 matcapColor = texture2D( matcap, uv );
	#else
		vec4 matcapColor = vec4( vec3( mix( 0.2, 0.8, uv.y ) ), 1.0 );
	#endif
	vec3 outgoingLight = diffuseColor.rgb * matcapColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,iy=`#define NORMAL
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	vViewPosition = - mvPosition.xyz;
#endif
}`,sy=`#define NORMAL
uniform float opacity;
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <uv_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 0.0, 0.0, 0.0, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	gl_FragColor = vec4( normalize( normal ) * 0.5 + 0.5, diffuseColor.a );
	#ifdef OPAQUE
		gl_FragColor.a = 1.0;
	#endif
}`,ry=`#define PHONG
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,oy=`#define PHONG
uniform vec3 diffuse;
uniform vec3 emissive;
uniform vec3 specular;
uniform float shininess;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_phong_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_phong_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + reflectedLight.directSpecular + reflectedLight.indirectSpecular + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,ay=`#define STANDARD
varying vec3 vViewPosition;
#ifdef USE_TRANSMISSION
	varying vec3 vWorldPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
#ifdef USE_TRANSMISSION
	vWorldPosition = worldPosition.xyz;
#endif
}`,ly=`#define STANDARD
#ifdef PHYSICAL
	#define IOR
	#define USE_SPECULAR
#endif
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float roughness;
uniform float metalness;
uniform float opacity;
#ifdef IOR
	uniform float ior;
#endif
#ifdef USE_SPECULAR
	uniform float specularIntensity;
	uniform vec3 specularColor;
	#ifdef USE_SPECULAR_COLORMAP
		uniform sampler2D specularColorMap;
	#endif
	#ifdef USE_SPECULAR_INTENSITYMAP
		uniform sampler2D specularIntensityMap;
	#endif
#endif
#ifdef USE_CLEARCOAT
	uniform float clearcoat;
	uniform float clearcoatRoughness;
#endif
#ifdef USE_DIFFUSE_ROUGHNESS
	uniform float diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		uniform sampler2D diffuseRoughnessMap;
	#endif
#endif
#ifdef USE_DISPERSION
	uniform float dispersion;
#endif
#ifdef USE_RETROREFLECTION
	uniform float retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	uniform float iridescence;
	uniform float iridescenceIOR;
	uniform float iridescenceThicknessMinimum;
	uniform float iridescenceThicknessMaximum;
#endif
#ifdef USE_SHEEN
	uniform vec3 sheenColor;
	uniform float sheenRoughness;
	#ifdef USE_SHEEN_COLORMAP
		uniform sampler2D sheenColorMap;
	#endif
	#ifdef USE_SHEEN_ROUGHNESSMAP
		uniform sampler2D sheenRoughnessMap;
	#endif
#endif
#ifdef USE_ANISOTROPY
	uniform vec2 anisotropyVector;
	#ifdef USE_ANISOTROPYMAP
		uniform sampler2D anisotropyMap;
	#endif
#endif
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <iridescence_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_physical_pars_fragment>
#include <transmission_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <clearcoat_pars_fragment>
#include <iridescence_pars_fragment>
#include <roughnessmap_pars_fragment>
#include <metalnessmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <roughnessmap_fragment>
	#include <metalnessmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <clearcoat_normal_fragment_begin>
	#include <clearcoat_normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_physical_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 totalDiffuse = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse;
	vec3 totalSpecular = reflectedLight.directSpecular + reflectedLight.indirectSpecular;
	#include <transmission_fragment>
	vec3 outgoingLight = totalDiffuse + totalSpecular + totalEmissiveRadiance;
	#ifdef USE_SHEEN
 
		outgoingLight = outgoingLight + sheenSpecularDirect + sheenSpecularIndirect;
 
 	#endif
	#ifdef USE_CLEARCOAT
		float dotNVcc = saturate( dot( geometryClearcoatNormal, geometryViewDir ) );
		vec3 Fcc = F_Schlick( material.clearcoatF0, material.clearcoatF90, dotNVcc );
		outgoingLight = outgoingLight * ( 1.0 - material.clearcoat * Fcc ) + ( clearcoatSpecularDirect + clearcoatSpecularIndirect ) * material.clearcoat;
	#endif
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,cy=`#define TOON
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,hy=`#define TOON
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <gradientmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_toon_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_toon_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,uy=`uniform float size;
uniform float scale;
#include <common>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
#ifdef USE_POINTS_UV
	varying vec2 vUv;
	uniform mat3 uvTransform;
#endif
void main() {
	#ifdef USE_POINTS_UV
		vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	#endif
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	gl_PointSize = size;
	#ifdef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) gl_PointSize *= ( scale / - mvPosition.z );
	#endif
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <fog_vertex>
}`,dy=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <color_pars_fragment>
#include <map_particle_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_particle_fragment>
	#include <color_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,fy=`#include <common>
#include <batching_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <shadowmap_pars_vertex>
void main() {
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,py=`uniform vec3 color;
uniform float opacity;
#include <common>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <logdepthbuf_pars_fragment>
#include <shadowmap_pars_fragment>
#include <shadowmask_pars_fragment>
void main() {
	#include <logdepthbuf_fragment>
	gl_FragColor = vec4( color, opacity * ( 1.0 - getShadowMask() ) );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,my=`uniform float rotation;
uniform vec2 center;
#include <common>
#include <uv_pars_vertex>
#include <fog_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	vec4 mvPosition = modelViewMatrix[ 3 ];
	vec2 scale = vec2( length( modelMatrix[ 0 ].xyz ), length( modelMatrix[ 1 ].xyz ) );
	#ifndef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) scale *= - mvPosition.z;
	#endif
	vec2 alignedPosition = ( position.xy - ( center - vec2( 0.5 ) ) ) * scale;
	vec2 rotatedPosition;
	rotatedPosition.x = cos( rotation ) * alignedPosition.x - sin( rotation ) * alignedPosition.y;
	rotatedPosition.y = sin( rotation ) * alignedPosition.x + cos( rotation ) * alignedPosition.y;
	mvPosition.xy += rotatedPosition;
	gl_Position = projectionMatrix * mvPosition;
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,gy=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
}`,dt={alphahash_fragment:B_,alphahash_pars_fragment:k_,alphamap_fragment:z_,alphamap_pars_fragment:V_,alphatest_fragment:H_,alphatest_pars_fragment:G_,aomap_fragment:W_,aomap_pars_fragment:$_,batching_pars_vertex:X_,batching_vertex:q_,begin_vertex:Y_,beginnormal_vertex:Z_,bsdfs:J_,iridescence_fragment:K_,bumpmap_pars_fragment:j_,clipping_planes_fragment:Q_,clipping_planes_pars_fragment:ex,clipping_planes_pars_vertex:tx,clipping_planes_vertex:nx,color_fragment:ix,color_pars_fragment:sx,color_pars_vertex:rx,color_vertex:ox,common:ax,defaultnormal_vertex:lx,displacementmap_pars_vertex:cx,displacementmap_vertex:hx,emissivemap_fragment:ux,emissivemap_pars_fragment:dx,colorspace_fragment:fx,colorspace_pars_fragment:px,envmap_fragment:mx,envmap_common_pars_fragment:gx,envmap_pars_fragment:_x,envmap_pars_vertex:xx,envmap_physical_pars_fragment:Cx,envmap_vertex:vx,fog_vertex:yx,fog_pars_vertex:bx,fog_fragment:Sx,fog_pars_fragment:Mx,gradientmap_pars_fragment:wx,lightmap_pars_fragment:Ex,lights_lambert_fragment:Tx,lights_lambert_pars_fragment:Ax,lights_pars_begin:Rx,lights_toon_fragment:Px,lights_toon_pars_fragment:Ix,lights_phong_fragment:Lx,lights_phong_pars_fragment:Dx,lights_physical_fragment:Nx,lights_physical_pars_fragment:Ux,lights_fragment_begin:Fx,lights_fragment_maps:Ox,lights_fragment_end:Bx,lightprobes_pars_fragment:kx,logdepthbuf_fragment:zx,logdepthbuf_pars_fragment:Vx,logdepthbuf_pars_vertex:Hx,logdepthbuf_vertex:Gx,map_fragment:Wx,map_pars_fragment:$x,map_particle_fragment:Xx,map_particle_pars_fragment:qx,metalnessmap_fragment:Yx,metalnessmap_pars_fragment:Zx,morphinstance_vertex:Jx,morphcolor_vertex:Kx,morphnormal_vertex:jx,morphtarget_pars_vertex:Qx,morphtarget_vertex:ev,normal_fragment_begin:tv,normal_fragment_maps:nv,normal_pars_fragment:iv,normal_pars_vertex:sv,normal_vertex:rv,normalmap_pars_fragment:ov,clearcoat_normal_fragment_begin:av,clearcoat_normal_fragment_maps:lv,clearcoat_pars_fragment:cv,iridescence_pars_fragment:hv,opaque_fragment:uv,packing:dv,premultiplied_alpha_fragment:fv,project_vertex:pv,dithering_fragment:mv,dithering_pars_fragment:gv,roughnessmap_fragment:_v,roughnessmap_pars_fragment:xv,shadowmap_pars_fragment:vv,shadowmap_pars_vertex:yv,shadowmap_vertex:bv,shadowmask_pars_fragment:Sv,skinbase_vertex:Mv,skinning_pars_vertex:wv,skinning_vertex:Ev,skinnormal_vertex:Tv,specularmap_fragment:Av,specularmap_pars_fragment:Rv,tonemapping_fragment:Cv,tonemapping_pars_fragment:Pv,transmission_fragment:Iv,transmission_pars_fragment:Lv,uv_pars_fragment:Dv,uv_pars_vertex:Nv,uv_vertex:Uv,worldpos_vertex:Fv,background_vert:Ov,background_frag:Bv,backgroundCube_vert:kv,backgroundCube_frag:zv,cube_vert:Vv,cube_frag:Hv,depth_vert:Gv,depth_frag:Wv,distance_vert:$v,distance_frag:Xv,equirect_vert:qv,equirect_frag:Yv,linedashed_vert:Zv,linedashed_frag:Jv,meshbasic_vert:Kv,meshbasic_frag:jv,meshlambert_vert:Qv,meshlambert_frag:ey,meshmatcap_vert:ty,meshmatcap_frag:ny,meshnormal_vert:iy,meshnormal_frag:sy,meshphong_vert:ry,meshphong_frag:oy,meshphysical_vert:ay,meshphysical_frag:ly,meshtoon_vert:cy,meshtoon_frag:hy,points_vert:uy,points_frag:dy,shadow_vert:fy,shadow_frag:py,sprite_vert:my,sprite_frag:gy},Ce={common:{diffuse:{value:new ct(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new st},alphaMap:{value:null},alphaMapTransform:{value:new st},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new st}},envmap:{envMap:{value:null},envMapRotation:{value:new st},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98},dfgLUT:{value:null}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new st}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new st}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new st},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new st},normalScale:{value:new je(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new st},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new st}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new st}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new st}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new ct(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},sunLights:{value:[],properties:{direction:{},color:{}}},sunLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},sunShadowMatrix:{value:[]},sunShadowCascade:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null},probesSH:{value:[]},probesMin:{value:[]},probesMax:{value:[]},probesResolution:{value:[]}},points:{diffuse:{value:new ct(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new st},alphaTest:{value:0},uvTransform:{value:new st}},sprite:{diffuse:{value:new ct(16777215)},opacity:{value:1},center:{value:new je(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new st},alphaMap:{value:null},alphaMapTransform:{value:new st},alphaTest:{value:0}}},Zn={basic:{uniforms:Bn([Ce.common,Ce.specularmap,Ce.envmap,Ce.aomap,Ce.lightmap,Ce.fog]),vertexShader:dt.meshbasic_vert,fragmentShader:dt.meshbasic_frag},lambert:{uniforms:Bn([Ce.common,Ce.specularmap,Ce.envmap,Ce.aomap,Ce.lightmap,Ce.emissivemap,Ce.bumpmap,Ce.normalmap,Ce.displacementmap,Ce.fog,Ce.lights,{emissive:{value:new ct(0)},envMapIntensity:{value:1}}]),vertexShader:dt.meshlambert_vert,fragmentShader:dt.meshlambert_frag},phong:{uniforms:Bn([Ce.common,Ce.specularmap,Ce.envmap,Ce.aomap,Ce.lightmap,Ce.emissivemap,Ce.bumpmap,Ce.normalmap,Ce.displacementmap,Ce.fog,Ce.lights,{emissive:{value:new ct(0)},specular:{value:new ct(1118481)},shininess:{value:30},envMapIntensity:{value:1}}]),vertexShader:dt.meshphong_vert,fragmentShader:dt.meshphong_frag},standard:{uniforms:Bn([Ce.common,Ce.envmap,Ce.aomap,Ce.lightmap,Ce.emissivemap,Ce.bumpmap,Ce.normalmap,Ce.displacementmap,Ce.roughnessmap,Ce.metalnessmap,Ce.fog,Ce.lights,{emissive:{value:new ct(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:dt.meshphysical_vert,fragmentShader:dt.meshphysical_frag},toon:{uniforms:Bn([Ce.common,Ce.aomap,Ce.lightmap,Ce.emissivemap,Ce.bumpmap,Ce.normalmap,Ce.displacementmap,Ce.gradientmap,Ce.fog,Ce.lights,{emissive:{value:new ct(0)}}]),vertexShader:dt.meshtoon_vert,fragmentShader:dt.meshtoon_frag},matcap:{uniforms:Bn([Ce.common,Ce.bumpmap,Ce.normalmap,Ce.displacementmap,Ce.fog,{matcap:{value:null}}]),vertexShader:dt.meshmatcap_vert,fragmentShader:dt.meshmatcap_frag},points:{uniforms:Bn([Ce.points,Ce.fog]),vertexShader:dt.points_vert,fragmentShader:dt.points_frag},dashed:{uniforms:Bn([Ce.common,Ce.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:dt.linedashed_vert,fragmentShader:dt.linedashed_frag},depth:{uniforms:Bn([Ce.common,Ce.displacementmap]),vertexShader:dt.depth_vert,fragmentShader:dt.depth_frag},normal:{uniforms:Bn([Ce.common,Ce.bumpmap,Ce.normalmap,Ce.displacementmap,{opacity:{value:1}}]),vertexShader:dt.meshnormal_vert,fragmentShader:dt.meshnormal_frag},sprite:{uniforms:Bn([Ce.sprite,Ce.fog]),vertexShader:dt.sprite_vert,fragmentShader:dt.sprite_frag},background:{uniforms:{uvTransform:{value:new st},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:dt.background_vert,fragmentShader:dt.background_frag},backgroundCube:{uniforms:{envMap:{value:null},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new st}},vertexShader:dt.backgroundCube_vert,fragmentShader:dt.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:dt.cube_vert,fragmentShader:dt.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:dt.equirect_vert,fragmentShader:dt.equirect_frag},distance:{uniforms:Bn([Ce.common,Ce.displacementmap,{referencePosition:{value:new W},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:dt.distance_vert,fragmentShader:dt.distance_frag},shadow:{uniforms:Bn([Ce.lights,Ce.fog,{color:{value:new ct(0)},opacity:{value:1}}]),vertexShader:dt.shadow_vert,fragmentShader:dt.shadow_frag}};Zn.physical={uniforms:Bn([Zn.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new st},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new st},clearcoatNormalScale:{value:new je(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new st},diffuseRoughness:{value:0},diffuseRoughnessMap:{value:null},diffuseRoughnessMapTransform:{value:new st},dispersion:{value:0},retroreflectivity:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new st},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new st},sheen:{value:0},sheenColor:{value:new ct(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new st},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new st},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new st},transmissionSamplerSize:{value:new je},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new st},attenuationDistance:{value:0},attenuationColor:{value:new ct(0)},specularColor:{value:new ct(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new st},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new st},anisotropyVector:{value:new je},anisotropyMap:{value:null},anisotropyMapTransform:{value:new st}}]),vertexShader:dt.meshphysical_vert,fragmentShader:dt.meshphysical_frag};var kc={r:0,b:0,g:0},_y=new kt,im=new st;im.set(-1,0,0,0,1,0,0,0,1);function xy(i,e,t,n,s,r){let o=new ct(0),a=s===!0?0:1,c,l,d=null,u=0,h=null;function m(y){let C=y.isScene===!0?y.background:null;if(C&&C.isTexture){let M=y.backgroundBlurriness>0;C=e.get(C,M)}return C}function g(y){let C=!1,M=m(y);M===null?p(o,a):M&&M.isColor&&(p(M,1),C=!0);let R=i.xr.getEnvironmentBlendMode();R==="additive"?t.buffers.color.setClear(0,0,0,1,r):R==="alpha-blend"&&t.buffers.color.setClear(0,0,0,0,r),(i.autoClear||C)&&(t.buffers.depth.setTest(!0),t.buffers.depth.setMask(!0),t.buffers.color.setMask(!0),i.clear(i.autoClearColor,i.autoClearDepth,i.autoClearStencil))}function v(y,C){let M=m(C);M&&M.isCubeTexture?(l===void 0&&(l=new Pn(new Qr(1,1,1),new yi({name:"BackgroundCubeMaterial",uniforms:hr(Zn.backgroundCube.uniforms),vertexShader:Zn.backgroundCube.vertexShader,fragmentShader:Zn.backgroundCube.fragmentShader,side:Yn,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),l.geometry.deleteAttribute("normal"),l.geometry.deleteAttribute("uv"),l.onBeforeRender=function(R,b,_){this.matrixWorld.copyPosition(_.matrixWorld)},Object.defineProperty(l.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),n.update(l)),l.material.uniforms.envMap.value=M,l.material.uniforms.backgroundBlurriness.value=C.backgroundBlurriness,l.material.uniforms.backgroundIntensity.value=C.backgroundIntensity,l.material.uniforms.backgroundRotation.value.setFromMatrix4(_y.makeRotationFromEuler(C.backgroundRotation)).transpose(),M.isRenderTargetTexture===!1&&l.material.uniforms.backgroundRotation.value.premultiply(im),l.material.toneMapped=_t.getTransfer(M.colorSpace)!==Rt,(d!==M||u!==M.version||h!==i.toneMapping)&&(l.material.needsUpdate=!0,d=M,u=M.version,h=i.toneMapping),l.layers.enableAll(),y.unshift(l,l.geometry,l.material,0,0,null)):M&&M.isTexture&&(c===void 0&&(c=new Pn(new sa(2,2),new yi({name:"BackgroundMaterial",uniforms:hr(Zn.background.uniforms),vertexShader:Zn.background.vertexShader,fragmentShader:Zn.background.fragmentShader,side:Ws,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),c.geometry.deleteAttribute("normal"),Object.defineProperty(c.material,"map",{get:function(){return this.uniforms.t2D.value}}),n.update(c)),c.material.uniforms.t2D.value=M,c.material.uniforms.backgroundIntensity.value=C.backgroundIntensity,c.material.toneMapped=_t.getTransfer(M.colorSpace)!==Rt,M.matrixAutoUpdate===!0&&M.updateMatrix(),c.material.uniforms.uvTransform.value.copy(M.matrix),(d!==M||u!==M.version||h!==i.toneMapping)&&(c.material.needsUpdate=!0,d=M,u=M.version,h=i.toneMapping),c.layers.enableAll(),y.unshift(c,c.geometry,c.material,0,0,null))}function p(y,C){y.getRGB(kc,Bu(i)),t.buffers.color.setClear(kc.r,kc.g,kc.b,C,r)}function f(){l!==void 0&&(l.geometry.dispose(),l.material.dispose(),l=void 0),c!==void 0&&(c.geometry.dispose(),c.material.dispose(),c=void 0)}return{getClearColor:function(){return o},setClearColor:function(y,C=1){o.set(y),a=C,p(o,a)},getClearAlpha:function(){return a},setClearAlpha:function(y){a=y,p(o,a)},render:g,addToRenderList:v,dispose:f}}function vy(i,e){let t=i.getParameter(i.MAX_VERTEX_ATTRIBS),n={},s=h(null),r=s,o=!1;function a(T,F,B,D,V){let Y=!1,$=u(T,D,B,F);r!==$&&(r=$,l(r.object)),Y=m(T,D,B,V),Y&&g(T,D,B,V),V!==null&&e.update(V,i.ELEMENT_ARRAY_BUFFER),(Y||o)&&(o=!1,M(T,F,B,D),V!==null&&i.bindBuffer(i.ELEMENT_ARRAY_BUFFER,e.get(V).buffer))}function c(){return i.createVertexArray()}function l(T){return i.bindVertexArray(T)}function d(T){return i.deleteVertexArray(T)}function u(T,F,B,D){let V=D.wireframe===!0,Y=n[F.id];Y===void 0&&(Y={},n[F.id]=Y);let $=T.isInstancedMesh===!0?T.id:0,ce=Y[$];ce===void 0&&(ce={},Y[$]=ce);let P=ce[B.id];P===void 0&&(P={},ce[B.id]=P);let I=P[V];return I===void 0&&(I=h(c()),P[V]=I),I}function h(T){let F=[],B=[],D=[];for(let V=0;V<t;V++)F[V]=0,B[V]=0,D[V]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:F,enabledAttributes:B,attributeDivisors:D,object:T,attributes:{},index:null}}function m(T,F,B,D){let V=r.attributes,Y=F.attributes,$=0,ce=B.getAttributes();for(let P in ce)if(ce[P].location>=0){let q=V[P],ie=Y[P];if(ie===void 0&&(P==="instanceMatrix"&&T.instanceMatrix&&(ie=T.instanceMatrix),P==="instanceColor"&&T.instanceColor&&(ie=T.instanceColor)),q===void 0||q.attribute!==ie||ie&&q.data!==ie.data)return!0;$++}return r.attributesNum!==$||r.index!==D}function g(T,F,B,D){let V={},Y=F.attributes,$=0,ce=B.getAttributes();for(let P in ce)if(ce[P].location>=0){let q=Y[P];q===void 0&&(P==="instanceMatrix"&&T.instanceMatrix&&(q=T.instanceMatrix),P==="instanceColor"&&T.instanceColor&&(q=T.instanceColor));let ie={};ie.attribute=q,q&&q.data&&(ie.data=q.data),V[P]=ie,$++}r.attributes=V,r.attributesNum=$,r.index=D}function v(){let T=r.newAttributes;for(let F=0,B=T.length;F<B;F++)T[F]=0}function p(T){f(T,0)}function f(T,F){let B=r.newAttributes,D=r.enabledAttributes,V=r.attributeDivisors;B[T]=1,D[T]===0&&(i.enableVertexAttribArray(T),D[T]=1),V[T]!==F&&(i.vertexAttribDivisor(T,F),V[T]=F)}function y(){let T=r.newAttributes,F=r.enabledAttributes;for(let B=0,D=F.length;B<D;B++)F[B]!==T[B]&&(i.disableVertexAttribArray(B),F[B]=0)}function C(T,F,B,D,V,Y,$){$===!0?i.vertexAttribIPointer(T,F,B,V,Y):i.vertexAttribPointer(T,F,B,D,V,Y)}function M(T,F,B,D){v();let V=D.attributes,Y=B.getAttributes(),$=F.defaultAttributeValues;for(let ce in Y){let P=Y[ce];if(P.location>=0){let I=V[ce];if(I===void 0&&(ce==="instanceMatrix"&&T.instanceMatrix&&(I=T.instanceMatrix),ce==="instanceColor"&&T.instanceColor&&(I=T.instanceColor)),I!==void 0){let q=I.normalized,ie=I.itemSize,he=e.get(I);if(he===void 0)continue;let Q=he.buffer,fe=he.type,le=he.bytesPerElement,me=fe===i.INT||fe===i.UNSIGNED_INT||I.gpuType===tc;if(I.isInterleavedBufferAttribute){let pe=I.data,De=pe.isInterleavedBuffer===!0?pe.stride:pe.itemSize,Ze=I.offset;if(pe.isInstancedInterleavedBuffer||pe.isInstancedBufferAttribute){for(let Ne=0;Ne<P.locationSize;Ne++)f(P.location+Ne,pe.meshPerAttribute);T.isInstancedMesh!==!0&&D._maxInstanceCount===void 0&&(D._maxInstanceCount=pe.meshPerAttribute*pe.count)}else for(let Ne=0;Ne<P.locationSize;Ne++)p(P.location+Ne);i.bindBuffer(i.ARRAY_BUFFER,Q);for(let Ne=0;Ne<P.locationSize;Ne++)C(P.location+Ne,ie/P.locationSize,fe,q,De*le,(Ze+ie/P.locationSize*Ne)*le,me)}else{if(I.isInstancedBufferAttribute){for(let pe=0;pe<P.locationSize;pe++)f(P.location+pe,I.meshPerAttribute);T.isInstancedMesh!==!0&&D._maxInstanceCount===void 0&&(D._maxInstanceCount=I.meshPerAttribute*I.count)}else for(let pe=0;pe<P.locationSize;pe++)p(P.location+pe);i.bindBuffer(i.ARRAY_BUFFER,Q);for(let pe=0;pe<P.locationSize;pe++)C(P.location+pe,ie/P.locationSize,fe,q,ie*le,ie/P.locationSize*pe*le,me)}}else if($!==void 0){let q=$[ce];if(q!==void 0)switch(q.length){case 2:i.vertexAttrib2fv(P.location,q);break;case 3:i.vertexAttrib3fv(P.location,q);break;case 4:i.vertexAttrib4fv(P.location,q);break;default:i.vertexAttrib1fv(P.location,q)}}}}y()}function R(){H();for(let T in n){let F=n[T];for(let B in F){let D=F[B];for(let V in D){let Y=D[V];for(let $ in Y)d(Y[$].object),delete Y[$];delete D[V]}}delete n[T]}}function b(T){if(n[T.id]===void 0)return;let F=n[T.id];for(let B in F){let D=F[B];for(let V in D){let Y=D[V];for(let $ in Y)d(Y[$].object),delete Y[$];delete D[V]}}delete n[T.id]}function _(T){for(let F in n){let B=n[F];for(let D in B){let V=B[D];if(V[T.id]===void 0)continue;let Y=V[T.id];for(let $ in Y)d(Y[$].object),delete Y[$];delete V[T.id]}}}function A(T){for(let F in n){let B=n[F],D=T.isInstancedMesh===!0?T.id:0,V=B[D];if(V!==void 0){for(let Y in V){let $=V[Y];for(let ce in $)d($[ce].object),delete $[ce];delete V[Y]}delete B[D],Object.keys(B).length===0&&delete n[F]}}}function H(){O(),o=!0,r!==s&&(r=s,l(r.object))}function O(){s.geometry=null,s.program=null,s.wireframe=!1}return{setup:a,reset:H,resetDefaultState:O,dispose:R,releaseStatesOfGeometry:b,releaseStatesOfObject:A,releaseStatesOfProgram:_,initAttributes:v,enableAttribute:p,disableUnusedAttributes:y}}function yy(i,e,t){let n;function s(c){n=c}function r(c,l){i.drawArrays(n,c,l),t.update(l,n,1)}function o(c,l,d){d!==0&&(i.drawArraysInstanced(n,c,l,d),t.update(l,n,d))}function a(c,l,d){if(d===0)return;e.get("WEBGL_multi_draw").multiDrawArraysWEBGL(n,c,0,l,0,d);let h=0;for(let m=0;m<d;m++)h+=l[m];t.update(h,n,1)}this.setMode=s,this.render=r,this.renderInstances=o,this.renderMultiDraw=a}function by(i,e,t,n){let s;function r(){if(s!==void 0)return s;if(e.has("EXT_texture_filter_anisotropic")===!0){let _=e.get("EXT_texture_filter_anisotropic");s=i.getParameter(_.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else s=0;return s}function o(_){return!(_!==Ui&&n.convert(_)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_FORMAT))}function a(_){let A=_===Ni&&(e.has("EXT_color_buffer_half_float")||e.has("EXT_color_buffer_float"));return!(_!==Qn&&_!==Di&&!A&&n.convert(_)!==i.getParameter(i.IMPLEMENTATION_COLOR_READ_TYPE))}function c(_){if(_==="highp"){if(i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.HIGH_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.HIGH_FLOAT).precision>0)return"highp";_="mediump"}return _==="mediump"&&i.getShaderPrecisionFormat(i.VERTEX_SHADER,i.MEDIUM_FLOAT).precision>0&&i.getShaderPrecisionFormat(i.FRAGMENT_SHADER,i.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let l=t.precision!==void 0?t.precision:"highp",d=c(l);d!==l&&(Ye("WebGLRenderer:",l,"not supported, using",d,"instead."),l=d);let u=t.reversedDepthBuffer===!0&&e.has("EXT_clip_control"),h=t.logarithmicDepthBuffer===!0&&u===!1;t.reversedDepthBuffer===!0&&u===!1&&Ye("WebGLRenderer: Unable to use reversed depth buffer due to missing EXT_clip_control extension. Fallback to default depth buffer."),t.logarithmicDepthBuffer===!0&&u===!0&&Ye("WebGLRenderer: Logarithmic depth buffer is ignored when reversed depth buffer is enabled.");let m=i.getParameter(i.MAX_TEXTURE_IMAGE_UNITS),g=i.getParameter(i.MAX_VERTEX_TEXTURE_IMAGE_UNITS),v=i.getParameter(i.MAX_TEXTURE_SIZE),p=i.getParameter(i.MAX_CUBE_MAP_TEXTURE_SIZE),f=i.getParameter(i.MAX_VERTEX_ATTRIBS),y=i.getParameter(i.MAX_VERTEX_UNIFORM_VECTORS),C=i.getParameter(i.MAX_VARYING_VECTORS),M=i.getParameter(i.MAX_FRAGMENT_UNIFORM_VECTORS),R=i.getParameter(i.MAX_SAMPLES),b=i.getParameter(i.SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:r,getMaxPrecision:c,textureFormatReadable:o,textureTypeReadable:a,precision:l,logarithmicDepthBuffer:h,reversedDepthBuffer:u,maxTextures:m,maxVertexTextures:g,maxTextureSize:v,maxCubemapSize:p,maxAttributes:f,maxVertexUniforms:y,maxVaryings:C,maxFragmentUniforms:M,maxSamples:R,samples:b}}function Sy(i){let e=this,t=null,n=0,s=!1,r=!1,o=new li,a=new st,c={value:null,needsUpdate:!1};this.uniform=c,this.numPlanes=0,this.numIntersection=0,this.init=function(u,h){let m=u.length!==0||h||n!==0||s;return s=h,n=u.length,m},this.beginShadows=function(){r=!0,d(null)},this.endShadows=function(){r=!1},this.setGlobalState=function(u,h){t=d(u,h,0)},this.setState=function(u,h,m){let g=u.clippingPlanes,v=u.clipIntersection,p=u.clipShadows,f=i.get(u);if(!s||g===null||g.length===0||r&&!p)r?d(null):l();else{let y=r?0:n,C=y*4,M=f.clippingState||null;c.value=M,M=d(g,h,C,m);for(let R=0;R!==C;++R)M[R]=t[R];f.clippingState=M,this.numIntersection=v?this.numPlanes:0,this.numPlanes+=y}};function l(){c.value!==t&&(c.value=t,c.needsUpdate=n>0),e.numPlanes=n,e.numIntersection=0}function d(u,h,m,g){let v=u!==null?u.length:0,p=null;if(v!==0){if(p=c.value,g!==!0||p===null){let f=m+v*4,y=h.matrixWorldInverse;a.getNormalMatrix(y),(p===null||p.length<f)&&(p=new Float32Array(f));for(let C=0,M=m;C!==v;++C,M+=4)o.copy(u[C]).applyMatrix4(y,a),o.normal.toArray(p,M),p[M+3]=o.constant}c.value=p,c.needsUpdate=!0}return e.numPlanes=v,e.numIntersection=0,p}}var Ia=class extends hi{constructor(e=1,t={}){super(e,e,t),this.isWebGLCubeRenderTarget=!0;let n={width:e,height:e,depth:1},s=[n,n,n,n,n,n];this.texture=new ta(s),this._setTextureOptions(t),this.texture.isRenderTargetTexture=!0}fromEquirectangularTexture(e,t){this.texture.type=t.type,this.texture.colorSpace=t.colorSpace,this.texture.generateMipmaps=t.generateMipmaps,this.texture.minFilter=t.minFilter,this.texture.magFilter=t.magFilter;let n={uniforms:{tEquirect:{value:null}},vertexShader:`

				varying vec3 vWorldDirection;

				vec3 transformDirection( in vec3 dir, in mat4 matrix ) {

					return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );

				}

				void main() {

					vWorldDirection = transformDirection( position, modelMatrix );

					#include <begin_vertex>
					#include <project_vertex>

				}
			`,fragmentShader:`

				uniform sampler2D tEquirect;

				varying vec3 vWorldDirection;

				#include <common>

				void main() {

					vec3 direction = normalize( vWorldDirection );

					vec2 sampleUV = equirectUv( direction );

					gl_FragColor = texture2D( tEquirect, sampleUV );

				}
			`},s=new Qr(5,5,5),r=new yi({name:"CubemapFromEquirect",uniforms:hr(n.uniforms),vertexShader:n.vertexShader,fragmentShader:n.fragmentShader,side:Yn,blending:or});r.uniforms.tEquirect.value=t;let o=new Pn(s,r),a=t.minFilter;return t.minFilter===ys&&(t.minFilter=Xn),new eo(1,10,this).update(e,o),t.minFilter=a,o.geometry.dispose(),o.material.dispose(),this}clear(e,t=!0,n=!0,s=!0){let r=e.getRenderTarget();for(let o=0;o<6;o++)e.setRenderTarget(this,o),e.clear(t,n,s);e.setRenderTarget(r)}},Up=256,My=3,wy=20,sm=256,rm=16,Ey=3,Ty=new W,Ay=new ct,Vc=class i{constructor(e){this._renderer=e,this._cubeSize=0,this._sourceTarget=null,this._cubeCamera=new eo(1,10,null),this._boxMesh=new Pn(new Qr(5,5,5),null),this._cubemapMaterial=null,this._equirectMaterial=null,this._blurMaterial=null,this._ggxMaterial=null,this._integrationMaterial=null}fromScene(e,t=0,n=.1,s=100,r={}){let{size:o=256,position:a=Ty}=r,c=this._renderer;this._setSize(o);let l=this._allocateTarget(),d=this._getSourceTarget(!0);t>0&&(d.texture.mipmapsAutoUpdate=!1);let u=c.autoClear,h=c.autoClearColor,m=c.autoClearDepth,g=c.autoClearStencil,v=e.background;c.autoClear=!0,c.autoClearColor=!0,c.autoClearDepth=!0,c.autoClearStencil=!0,v===null&&(e.background=c.getClearColor(Ay));let p=new eo(n,s,d);return p.position.copy(a),p.update(c,e),c.autoClear=u,c.autoClearColor=h,c.autoClearDepth=m,c.autoClearStencil=g,e.background=v,t>0&&(d.texture.mipmapsAutoUpdate=!0,this._blur(l,t)),this._applyPMREM(l),l}fromEquirectangular(e,t=null){return this._fromTexture(e,t)}fromCubemap(e,t=null){return this._fromTexture(e,t)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=Bp(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=Op(),this._compileMaterial(this._equirectMaterial))}dispose(){this._sourceTarget!==null&&this._sourceTarget.dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose(),this._blurMaterial!==null&&this._blurMaterial.dispose(),this._ggxMaterial!==null&&this._ggxMaterial.dispose(),this._integrationMaterial!==null&&this._integrationMaterial.dispose(),this._boxMesh.geometry.dispose()}static lodToRoughness(e,t){return t>0?1-Math.sqrt(1-e/t):0}_setSize(e){this._cubeSize=Math.max(Up,Uu(e))}_fromTexture(e,t){e.mapping===lr||e.mapping===so?this._setSize(e.image.length===0?Up:e.image[0].width||e.image[0].image.width):this._setSize(e.image.width/4);let n=t||this._allocateTarget();return this._textureToCubemap(e),this._applyPMREM(n),n}_allocateTarget(){let e=this._cubeSize,t=Fp(e,!1,!1),n=Math.log2(e)-My;for(let s=0;s<=n;s++)t.texture.mipmaps.push({width:e>>s,height:e>>s});return t.texture.name="PMREM",t.texture.isPMREMTexture=!0,t}_getSourceTarget(e=!1){let t=this._cubeSize,n=this._sourceTarget;return(n===null||n.width!==t||e&&n.depthBuffer===!1)&&(n!==null&&n.dispose(),this._sourceTarget=Fp(t,!0,e)),this._sourceTarget}_compileMaterial(e){this._boxMesh.material=e,this._renderer.compile(this._boxMesh,this._cubeCamera.children[0])}_renderCube(e,t,n){let s=this._boxMesh,r=this._cubeCamera;s.material=n,r.renderTarget=e,r.activeMipmapLevel=t;let o=e.width>>t;e.viewport.set(0,0,o,o),r.update(this._renderer,s),e.viewport.set(0,0,e.width,e.height)}_textureToCubemap(e){let t;e.mapping===lr||e.mapping===so?(this._cubemapMaterial===null&&(this._cubemapMaterial=Bp()),t=this._cubemapMaterial,t.uniforms.flipEnvMap.value=e.isRenderTargetTexture===!1?-1:1):(this._equirectMaterial===null&&(this._equirectMaterial=Op()),t=this._equirectMaterial),t.uniforms.envMap.value=e,this._renderCube(this._getSourceTarget(),0,t)}_applyPMREM(e){this._ggxMaterial===null&&(this._ggxMaterial=Ry(),this._integrationMaterial=Cy());let t=this._cubeSize,n=e.texture.mipmaps.length-1,s=this._ggxMaterial.uniforms;s.envMap.value=this._sourceTarget.texture;let r=this._integrationMaterial.uniforms;r.envMap.value=this._sourceTarget.texture,r.sourceLod.value=Math.log2(t/rm);for(let o=0;o<=n;o++){let a=i.lodToRoughness(o,n);if(o>n-Ey)r.roughness.value=a,this._renderCube(e,o,this._integrationMaterial);else{let c=a>0?Math.log2(t)+.5*Math.log2(6/(sm*Math.pow(a,4)))+.5:0;s.roughness.value=a,s.lodBias.value=c,this._renderCube(e,o,this._ggxMaterial)}}}_blur(e,t){this._blurMaterial===null&&(this._blurMaterial=Py());let n=this._blurMaterial,s=n.uniforms,r=this._sourceTarget;s.sigma.value=Math.min(t,Math.PI)/Math.SQRT2,s.envMap.value=r.texture,this._renderCube(e,0,n),s.envMap.value=e.texture,this._renderCube(r,0,n)}};function Fp(i,e,t){return new Ia(i,{minFilter:ys,generateMipmaps:e,type:Ni,colorSpace:$o,depthBuffer:t})}function La(i,e,t){return new yi({name:i,uniforms:e,vertexShader:dt.cube_vert,fragmentShader:t,side:Yn,blending:or,depthTest:!1,depthWrite:!1})}function Ry(){return La("PMREMGGXConvolution",{envMap:{value:null},roughness:{value:0},lodBias:{value:0}},`

		#define GGX_SAMPLES ${sm}u

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float lodBias;

		#include <common>

		// Van der Corput radical inverse
		float radicalInverse_VdC( uint bits ) {

			bits = ( bits << 16u ) | ( bits >> 16u );
			bits = ( ( bits & 0x55555555u ) << 1u ) | ( ( bits & 0xAAAAAAAAu ) >> 1u );
			bits = ( ( bits & 0x33333333u ) << 2u ) | ( ( bits & 0xCCCCCCCCu ) >> 2u );
			bits = ( ( bits & 0x0F0F0F0Fu ) << 4u ) | ( ( bits & 0xF0F0F0F0u ) >> 4u );
			bits = ( ( bits & 0x00FF00FFu ) << 8u ) | ( ( bits & 0xFF00FF00u ) >> 8u );
			return float( bits ) * 2.3283064365386963e-10; // / 0x100000000

		}

		// Hammersley sequence
		vec2 hammersley( uint i, uint N ) {

			return vec2( float( i ) / float( N ), radicalInverse_VdC( i ) );

		}

		void main() {

			vec3 N = normalize( vWorldDirection );

			// For very low roughness, just sample the environment directly
			if ( roughness < 0.001 ) {

				gl_FragColor = vec4( textureLod( envMap, N, 0.0 ).rgb, 1.0 );
				return;

			}

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			// Tangent space basis for VNDF sampling
			vec3 up = abs( N.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, N ) );
			vec3 bitangent = cross( N, tangent );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			for ( uint i = 0u; i < GGX_SAMPLES; i ++ ) {

				vec2 Xi = hammersley( i, GGX_SAMPLES );

				// With V = N, sample the reflected direction directly.
				float invQ = 1.0 / ( 1.0 - Xi.x + alpha2 * Xi.x );
				float NdotL = ( 1.0 - Xi.x - alpha2 * Xi.x ) * invQ;

				if ( NdotL > 0.0 ) {

					float phi = 2.0 * PI * Xi.y;
					float sinTheta = 2.0 * alpha * sqrt( Xi.x * ( 1.0 - Xi.x ) ) * invQ;
					vec3 L = N * NdotL + ( tangent * cos( phi ) + bitangent * sin( phi ) ) * sinTheta;

					// Match the source mip to the sample's solid angle. The terms
					// independent of the sample are precomputed in lodBias.
					float d = alpha2 * invQ;
					float lod = max( log2( d ) + lodBias, 0.0 );

					// Weight by NdotL for the split-sum approximation
					prefilteredColor += textureLod( envMap, L, lod ).rgb * NdotL;
					totalWeight += NdotL;

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function Cy(){return La("PMREMGGXIntegration",{envMap:{value:null},roughness:{value:0},sourceLod:{value:0},sourceSize:{value:rm}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float sourceLod;
		uniform int sourceSize;

		void main() {

			vec3 N = normalize( vWorldDirection );

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			float texelSize = 2.0 / float( sourceSize );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			// Pair opposite texels: only the one in N's hemisphere contributes.
			for ( int face = 0; face < 3; face ++ ) {

				for ( int y = 0; y < sourceSize; y ++ ) {

					for ( int x = 0; x < sourceSize; x ++ ) {

						vec2 uv = ( vec2( x, y ) + 0.5 ) * texelSize - 1.0;
						vec3 texelDirection = face == 0 ? vec3( 1.0, uv ) : ( face == 1 ? vec3( uv.x, 1.0, uv.y ) : vec3( uv, 1.0 ) );

						float invDistance = inversesqrt( 1.0 + dot( uv, uv ) );
						float NdotL = dot( N, texelDirection );
						texelDirection *= NdotL < 0.0 ? - 1.0 : 1.0;
						NdotL = abs( NdotL ) * invDistance;

						// With V = N, NdotH squared is ( 1 + NdotL ) / 2. Common factors
						// in the GGX distribution and texel solid angle cancel when normalized.
						float d = 1.0 + alpha2 + ( alpha2 - 1.0 ) * NdotL;
						float weight = NdotL * invDistance * invDistance * invDistance / ( d * d );

						prefilteredColor += textureLod( envMap, texelDirection, sourceLod ).rgb * weight;
						totalWeight += weight;

					}

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function Py(){return La("PMREMSphericalGaussianBlur",{envMap:{value:null},sigma:{value:0}},`

		#define SAMPLES ${wy}
		#define GOLDEN_ANGLE 2.39996322973

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float sigma;

		#include <common>

		void main() {

			vec3 outputDirection = normalize( vWorldDirection );

			vec3 up = abs( outputDirection.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, outputDirection ) );
			vec3 bitangent = cross( outputDirection, tangent );

			// Truncate the kernel at three standard deviations or at the antipode.
			float thetaMax = min( 3.0 * sigma, PI );
			float truncation = 1.0 - exp( - 0.5 * thetaMax * thetaMax / ( sigma * sigma ) );

			vec3 accumColor = vec3( 0.0 );
			float accumWeight = 0.0;

			for ( int i = 0; i < SAMPLES; i ++ ) {

				// Stratified inverse-CDF sampling of the Gaussian, placed on a golden-angle spiral.
				float stratum = ( float( i ) + 0.5 ) / float( SAMPLES );
				float theta = sigma * sqrt( - 2.0 * log( 1.0 - stratum * truncation ) );
				float phi = float( i ) * GOLDEN_ANGLE;

				vec3 offset = cos( phi ) * tangent + sin( phi ) * bitangent;
				vec3 sampleDirection = cos( theta ) * outputDirection + sin( theta ) * offset;

				// Correct the planar sample density to solid angle.
				float weight = sin( theta ) / theta;

				accumColor += weight * textureLod( envMap, sampleDirection, 0.0 ).rgb;
				accumWeight += weight;

			}

			gl_FragColor = vec4( accumColor / accumWeight, 1.0 );

		}
	`)}function Op(){return La("PMREMEquirectangularToCubemap",{envMap:{value:null}},`

		varying vec3 vWorldDirection;

		uniform sampler2D envMap;

		#include <common>

		void main() {

			// Average four subpixel samples to preserve small, bright features.
			vec3 direction = normalize( vWorldDirection );
			vec3 dx = dFdx( direction ) * 0.25;
			vec3 dy = dFdy( direction ) * 0.25;

			vec3 color = textureLod( envMap, equirectUv( normalize( direction - dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction - dx + dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx + dy ) ), 0.0 ).rgb;
			gl_FragColor = vec4( color * 0.25, 1.0 );

		}
	`)}function Bp(){return La("PMREMCubemapToCubemap",{envMap:{value:null},flipEnvMap:{value:-1}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float flipEnvMap;

		void main() {

			gl_FragColor = vec4( textureCube( envMap, vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) ).rgb, 1.0 );

		}
	`)}function Iy(i){let e=new WeakMap,t=new WeakMap,n=null;function s(h,m=!1){return h==null?null:m?o(h):r(h)}function r(h){if(h&&h.isTexture){let m=h.mapping;if(m===jl||m===Ql)if(e.has(h)){let g=e.get(h).texture;return a(g,h.mapping)}else{let g=h.image;if(g&&g.height>0){let v=new Ia(g.height);return v.fromEquirectangularTexture(i,h),e.set(h,v),h.addEventListener("dispose",l),a(v.texture,h.mapping)}else return null}}return h}function o(h){if(h&&h.isTexture&&h.isPMREMTexture!==!0){let m=h.mapping,g=m===jl||m===Ql,v=m===lr||m===so;if(g||v){let p=t.get(h),f=p!==void 0?p.texture.pmremVersion:0;if(h.isRenderTargetTexture&&h.pmremVersion!==f)return n===null&&(n=new Vc(i)),p=g?n.fromEquirectangular(h,p):n.fromCubemap(h,p),p.texture.pmremVersion=h.pmremVersion,t.set(h,p),p.texture;if(p!==void 0)return p.texture;{let y=h.image;return g&&y&&y.height>0||v&&y&&c(y)?(n===null&&(n=new Vc(i)),p=g?n.fromEquirectangular(h):n.fromCubemap(h),p.texture.pmremVersion=h.pmremVersion,t.set(h,p),h.addEventListener("dispose",d),p.texture):null}}}return h}function a(h,m){return m===jl?h.mapping=lr:m===Ql&&(h.mapping=so),h}function c(h){let m=0,g=6;for(let v=0;v<g;v++)h[v]!==void 0&&m++;return m===g}function l(h){let m=h.target;m.removeEventListener("dispose",l);let g=e.get(m);g!==void 0&&(e.delete(m),g.dispose())}function d(h){let m=h.target;m.removeEventListener("dispose",d);let g=t.get(m);g!==void 0&&(t.delete(m),g.dispose())}function u(){e=new WeakMap,t=new WeakMap,n!==null&&(n.dispose(),n=null)}return{get:s,dispose:u}}function Ly(i){let e={};function t(n){if(e[n]!==void 0)return e[n];let s=i.getExtension(n);return e[n]=s,s}return{has:function(n){return t(n)!==null},init:function(){t("EXT_color_buffer_float"),t("WEBGL_clip_cull_distance"),t("OES_texture_float_linear"),t("EXT_color_buffer_half_float"),t("WEBGL_multisampled_render_to_texture"),t("WEBGL_render_shared_exponent")},get:function(n){let s=t(n);return s===null&&Vo("WebGLRenderer: "+n+" extension not supported."),s}}}function Dy(i,e,t,n){let s={},r=new WeakMap,o=new FinalizationRegistry(g=>delete s[g]);function a(g){c(g.target)}function c(g){g.index!==null&&e.remove(g.index);for(let p in g.attributes)e.remove(g.attributes[p]);g.removeEventListener("dispose",a),delete s[g.id],o.unregister(g);let v=r.get(g);v&&(e.remove(v),r.delete(g)),n.releaseStatesOfGeometry(g),g.isInstancedBufferGeometry===!0&&delete g._maxInstanceCount,t.memory.geometries--}function l(g,v){return s[v.id]!==void 0||(v.addEventListener("dispose",a),s[v.id]=new WeakRef(v),o.register(v,v.id,v),t.memory.geometries++),v}function d(g){let v=g.attributes;for(let p in v)e.update(v[p],i.ARRAY_BUFFER)}function u(g){let v=g.index,p=g.attributes.position,f=0;if(p===void 0)return;let y=v!==null?v.array.length:p.array.length/3-1,C=p.count>=65535?Qo:jo,M=new C(Math.ceil(y/3)*6,1),R=M.array;if(v!==null){let _=v.array;f=v.version;for(let A=0,H=0;A<y;A+=3){let O=_[A+0],T=_[A+1],F=_[A+2];R[H++]=O,R[H++]=T,R[H++]=T,R[H++]=F,R[H++]=F,R[H++]=O}}else{f=p.version;for(let _=0,A=0;_<y;_+=3){let H=_+0,O=_+1,T=_+2;R[A++]=H,R[A++]=O,R[A++]=O,R[A++]=T,R[A++]=T,R[A++]=H}}M.version=f;let b=r.get(g);b&&e.remove(b),r.set(g,M)}function h(g){let v=r.get(g);if(v){let p=g.index;p!==null&&v.version<p.version&&u(g)}else u(g);return r.get(g)}function m(){for(let g in s){let v=s[g].deref();v!==void 0&&c(v)}}return{get:l,update:d,getWireframeAttribute:h,dispose:m}}function Ny(i,e,t){let n;function s(u){n=u}let r,o;function a(u){r=u.type,o=u.bytesPerElement}function c(u,h){i.drawElements(n,h,r,u*o),t.update(h,n,1)}function l(u,h,m){m!==0&&(i.drawElementsInstanced(n,h,r,u*o,m),t.update(h,n,m))}function d(u,h,m){if(m===0)return;e.get("WEBGL_multi_draw").multiDrawElementsWEBGL(n,h,0,r,u,0,m);let v=0;for(let p=0;p<m;p++)v+=h[p];t.update(v,n,1)}this.setMode=s,this.setIndex=a,this.render=c,this.renderInstances=l,this.renderMultiDraw=d}function Uy(i){let e={geometries:0,textures:0},t={frame:0,calls:0,triangles:0,points:0,lines:0};function n(r,o,a){switch(t.calls++,o){case i.TRIANGLES:t.triangles+=a*(r/3);break;case i.LINES:t.lines+=a*(r/2);break;case i.LINE_STRIP:t.lines+=a*(r-1);break;case i.LINE_LOOP:t.lines+=a*r;break;case i.POINTS:t.points+=a*r;break;default:it("WebGLInfo: Unknown draw mode:",o);break}}function s(){t.calls=0,t.triangles=0,t.points=0,t.lines=0}return{memory:e,render:t,programs:null,autoReset:!0,reset:s,update:n}}function Fy(i,e,t){let n=new WeakMap,s=new Ct;function r(o,a,c){let l=o.morphTargetInfluences,d=a.morphAttributes.position||a.morphAttributes.normal||a.morphAttributes.color,u=d!==void 0?d.length:0,h=n.get(a);if(h===void 0||h.count!==u){let H=function(){_.dispose(),n.delete(a),a.removeEventListener("dispose",H)};h!==void 0&&h.texture.dispose();let m=a.morphAttributes.position!==void 0,g=a.morphAttributes.normal!==void 0,v=a.morphAttributes.color!==void 0,p=a.morphAttributes.position||[],f=a.morphAttributes.normal||[],y=a.morphAttributes.color||[],C=0;m===!0&&(C=1),g===!0&&(C=2),v===!0&&(C=3);let M=a.attributes.position.count*C,R=1;M>e.maxTextureSize&&(R=Math.ceil(M/e.maxTextureSize),M=e.maxTextureSize);let b=new Float32Array(M*R*4*u),_=new Zo(b,M,R,u);_.type=Di,_.needsUpdate=!0;let A=C*4;for(let O=0;O<u;O++){let T=p[O],F=f[O],B=y[O],D=M*R*4*O;for(let V=0;V<T.count;V++){let Y=V*A;m===!0&&(s.fromBufferAttribute(T,V),b[D+Y+0]=s.x,b[D+Y+1]=s.y,b[D+Y+2]=s.z,b[D+Y+3]=0),g===!0&&(s.fromBufferAttribute(F,V),b[D+Y+4]=s.x,b[D+Y+5]=s.y,b[D+Y+6]=s.z,b[D+Y+7]=0),v===!0&&(s.fromBufferAttribute(B,V),b[D+Y+8]=s.x,b[D+Y+9]=s.y,b[D+Y+10]=s.z,b[D+Y+11]=B.itemSize===4?s.w:1)}}h={count:u,texture:_,size:new je(M,R)},n.set(a,h),a.addEventListener("dispose",H)}if(o.isInstancedMesh===!0&&o.morphTexture!==null)c.getUniforms().setValue(i,"morphTexture",o.morphTexture,t);else{let m=0;for(let v=0;v<l.length;v++)m+=l[v];let g=a.morphTargetsRelative?1:1-m;c.getUniforms().setValue(i,"morphTargetBaseInfluence",g),c.getUniforms().setValue(i,"morphTargetInfluences",l)}c.getUniforms().setValue(i,"morphTargetsTexture",h.texture,t),c.getUniforms().setValue(i,"morphTargetsTextureSize",h.size)}return{update:r}}function Oy(i,e,t,n,s){let r=new WeakMap;function o(l){let d=s.render.frame,u=l.geometry,h=e.get(l,u);if(r.get(h)!==d&&(e.update(h),r.set(h,d)),l.isInstancedMesh&&(l.hasEventListener("dispose",c)===!1&&l.addEventListener("dispose",c),r.get(l)!==d&&(t.update(l.instanceMatrix,i.ARRAY_BUFFER),l.instanceColor!==null&&t.update(l.instanceColor,i.ARRAY_BUFFER),r.set(l,d))),l.isSkinnedMesh){let m=l.skeleton;r.get(m)!==d&&(m.update(),r.set(m,d))}return h}function a(){r=new WeakMap}function c(l){let d=l.target;d.removeEventListener("dispose",c),n.releaseStatesOfObject(d),t.remove(d.instanceMatrix),d.instanceColor!==null&&t.remove(d.instanceColor)}return{update:o,dispose:a}}var By={[pu]:"LINEAR_TONE_MAPPING",[mu]:"REINHARD_TONE_MAPPING",[gu]:"CINEON_TONE_MAPPING",[_u]:"ACES_FILMIC_TONE_MAPPING",[vu]:"AGX_TONE_MAPPING",[yu]:"NEUTRAL_TONE_MAPPING",[xu]:"CUSTOM_TONE_MAPPING"};function ky(i,e,t,n,s,r){let o=new hi(e,t,{type:i,depthBuffer:s,stencilBuffer:r,samples:n?4:0,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,resolveDepthBuffer:!1,resolveStencilBuffer:!1}),a=null,c=null,l=null,d=new An;d.setAttribute("position",new Ot([-1,3,0,-1,-1,0,3,-1,0],3)),d.setAttribute("uv",new Ot([0,2,0,0,2,0],2));let u=new Fl({uniforms:{tDiffuse:{value:null}},vertexShader:`
			precision highp float;

			uniform mat4 modelViewMatrix;
			uniform mat4 projectionMatrix;

			attribute vec3 position;
			attribute vec2 uv;

			varying vec2 vUv;

			void main() {
				vUv = uv;
				gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
			}`,fragmentShader:`
			precision highp float;

			uniform sampler2D tDiffuse;

			varying vec2 vUv;

			#include <tonemapping_pars_fragment>
			#include <colorspace_pars_fragment>

			void main() {
				gl_FragColor = texture2D( tDiffuse, vUv );

				#ifdef LINEAR_TONE_MAPPING
					gl_FragColor.rgb = LinearToneMapping( gl_FragColor.rgb );
				#elif defined( REINHARD_TONE_MAPPING )
					gl_FragColor.rgb = ReinhardToneMapping( gl_FragColor.rgb );
				#elif defined( CINEON_TONE_MAPPING )
					gl_FragColor.rgb = CineonToneMapping( gl_FragColor.rgb );
				#elif defined( ACES_FILMIC_TONE_MAPPING )
					gl_FragColor.rgb = ACESFilmicToneMapping( gl_FragColor.rgb );
				#elif defined( AGX_TONE_MAPPING )
					gl_FragColor.rgb = AgXToneMapping( gl_FragColor.rgb );
				#elif defined( NEUTRAL_TONE_MAPPING )
					gl_FragColor.rgb = NeutralToneMapping( gl_FragColor.rgb );
				#elif defined( CUSTOM_TONE_MAPPING )
					gl_FragColor.rgb = CustomToneMapping( gl_FragColor.rgb );
				#endif

				#ifdef SRGB_TRANSFER
					gl_FragColor = sRGBTransferOETF( gl_FragColor );
				#endif
			}`,depthTest:!1,depthWrite:!1}),h=new Pn(d,u),m=new da(-1,1,1,-1,0,1),g=null,v=null,p=!1,f,y=null,C=[],M=!1;this.setSize=function(R,b){o.setSize(R,b),a!==null&&a.setSize(R,b),c!==null&&c.setSize(R,b);for(let _=0;_<C.length;_++){let A=C[_];A.setSize&&A.setSize(R,b)}},this.setEffects=function(R){C=R,M=C.length>0&&C[0].isRenderPass===!0;let b=o.width,_=o.height;C.length>0&&a===null&&(a=new hi(b,_,{type:Ni,depthBuffer:!1,stencilBuffer:!1}),c=new hi(b,_,{type:Ni,depthBuffer:!1,stencilBuffer:!1}));let A=s===!0&&C.some(H=>H.needsDepthTexture===!0);A!==(o.depthTexture!==null)&&(A===!0&&l===null&&(l=new vs(b,_),r===!0&&(l.format=bs,l.type=cr)),o.dispose(),o.depthTexture=A?l:null,o.resolveDepthBuffer=A,o.storeMultisampledDepthBuffer=A);for(let H=0;H<C.length;H++){let O=C[H];O.setSize&&O.setSize(b,_),A&&O.needsDepthTexture===!0&&O.setDepthTexture&&O.setDepthTexture(l)}},this.begin=function(R,b){if(p||R.toneMapping===Ji&&C.length===0)return!1;if(y=b,b!==null){let _=b.width,A=b.height;(o.width!==_||o.height!==A)&&this.setSize(_,A)}return M===!1&&R.setRenderTarget(o),f=R.toneMapping,R.toneMapping=Ji,!0},this.hasRenderPass=function(){return M},this.end=function(R,b){R.toneMapping=f,p=!0;let _=o,A=a;for(let H=0;H<C.length;H++){let O=C[H];O.enabled!==!1&&(O.render(R,A,_,b),O.needsSwap!==!1&&(_=A,A=A===a?c:a))}if(g!==R.outputColorSpace||v!==R.toneMapping){g=R.outputColorSpace,v=R.toneMapping,u.defines={},_t.getTransfer(g)===Rt&&(u.defines.SRGB_TRANSFER="");let H=By[v];H&&(u.defines[H]=""),u.needsUpdate=!0}u.uniforms.tDiffuse.value=_.texture,R.setRenderTarget(y),R.render(h,m),y=null,p=!1},this.isCompositing=function(){return p},this.dispose=function(){o.dispose(),a!==null&&a.dispose(),c!==null&&c.dispose(),d.dispose(),u.dispose()}}var om=new jn,am=new vs(1,1),lm=new na(1),cm=new Zo,hm=new Pl,um=new ta,kp=[],zp=[],Vp=new Float32Array(16),Hp=new Float32Array(9),Gp=new Float32Array(4);function ao(i,e,t){let n=i[0];if(n<=0||n>0)return i;let s=e*t,r=kp[s];if(r===void 0&&(r=new Float32Array(s),kp[s]=r),e!==0){n.toArray(r,0);for(let o=1,a=0;o!==e;++o)a+=t,i[o].toArray(r,a)}return r}function mn(i,e){if(i.length!==e.length)return!1;for(let t=0,n=i.length;t<n;t++)if(i[t]!==e[t])return!1;return!0}function gn(i,e){for(let t=0,n=e.length;t<n;t++)i[t]=e[t]}function Gc(i,e){let t=zp[e];t===void 0&&(t=new Int32Array(e),zp[e]=t);for(let n=0;n!==e;++n)t[n]=i.allocateTextureUnit();return t}function zy(i,e){let t=this.cache;t[0]!==e&&(i.uniform1f(this.addr,e),t[0]=e)}function Vy(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(i.uniform2f(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(mn(t,e))return;i.uniform2fv(this.addr,e),gn(t,e)}}function Hy(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(i.uniform3f(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else if(e.r!==void 0)(t[0]!==e.r||t[1]!==e.g||t[2]!==e.b)&&(i.uniform3f(this.addr,e.r,e.g,e.b),t[0]=e.r,t[1]=e.g,t[2]=e.b);else{if(mn(t,e))return;i.uniform3fv(this.addr,e),gn(t,e)}}function Gy(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(i.uniform4f(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(mn(t,e))return;i.uniform4fv(this.addr,e),gn(t,e)}}function Wy(i,e){let t=this.cache,n=e.elements;if(n===void 0){if(mn(t,e))return;i.uniformMatrix2fv(this.addr,!1,e),gn(t,e)}else{if(mn(t,n))return;Gp.set(n),i.uniformMatrix2fv(this.addr,!1,Gp),gn(t,n)}}function $y(i,e){let t=this.cache,n=e.elements;if(n===void 0){if(mn(t,e))return;i.uniformMatrix3fv(this.addr,!1,e),gn(t,e)}else{if(mn(t,n))return;Hp.set(n),i.uniformMatrix3fv(this.addr,!1,Hp),gn(t,n)}}function Xy(i,e){let t=this.cache,n=e.elements;if(n===void 0){if(mn(t,e))return;i.uniformMatrix4fv(this.addr,!1,e),gn(t,e)}else{if(mn(t,n))return;Vp.set(n),i.uniformMatrix4fv(this.addr,!1,Vp),gn(t,n)}}function qy(i,e){let t=this.cache;t[0]!==e&&(i.uniform1i(this.addr,e),t[0]=e)}function Yy(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(i.uniform2i(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(mn(t,e))return;i.uniform2iv(this.addr,e),gn(t,e)}}function Zy(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(i.uniform3i(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(mn(t,e))return;i.uniform3iv(this.addr,e),gn(t,e)}}function Jy(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(i.uniform4i(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(mn(t,e))return;i.uniform4iv(this.addr,e),gn(t,e)}}function Ky(i,e){let t=this.cache;t[0]!==e&&(i.uniform1ui(this.addr,e),t[0]=e)}function jy(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(i.uniform2ui(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(mn(t,e))return;i.uniform2uiv(this.addr,e),gn(t,e)}}function Qy(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(i.uniform3ui(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(mn(t,e))return;i.uniform3uiv(this.addr,e),gn(t,e)}}function eb(i,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(i.uniform4ui(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(mn(t,e))return;i.uniform4uiv(this.addr,e),gn(t,e)}}function Wc(i){return i.version===0&&(i.compareFunction=Iu,i.needsUpdate=!0),i}function tb(i,e,t){let n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s);let r;this.type===i.SAMPLER_2D_SHADOW?r=Wc(am):r=om,t.setTexture2D(e||r,s)}function nb(i,e,t){let n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s),t.setTexture3D(e||hm,s)}function ib(i,e,t){let n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s);let r;this.type===i.SAMPLER_CUBE_SHADOW?r=Wc(lm):r=um,t.setTextureCube(e||r,s)}function sb(i,e,t){let n=this.cache,s=t.allocateTextureUnit();n[0]!==s&&(i.uniform1i(this.addr,s),n[0]=s),t.setTexture2DArray(e||cm,s)}function rb(i){switch(i){case 5126:return zy;case 35664:return Vy;case 35665:return Hy;case 35666:return Gy;case 35674:return Wy;case 35675:return $y;case 35676:return Xy;case 5124:case 35670:return qy;case 35667:case 35671:return Yy;case 35668:case 35672:return Zy;case 35669:case 35673:return Jy;case 5125:return Ky;case 36294:return jy;case 36295:return Qy;case 36296:return eb;case 35678:case 36198:case 36298:case 36306:case 35682:return tb;case 35679:case 36299:case 36307:return nb;case 35680:case 36300:case 36308:case 36293:return ib;case 36289:case 36303:case 36311:case 36292:return sb}}function ob(i,e){i.uniform1fv(this.addr,e)}function ab(i,e){let t=ao(e,this.size,2);i.uniform2fv(this.addr,t)}function lb(i,e){let t=ao(e,this.size,3);i.uniform3fv(this.addr,t)}function cb(i,e){let t=ao(e,this.size,4);i.uniform4fv(this.addr,t)}function hb(i,e){let t=ao(e,this.size,4);i.uniformMatrix2fv(this.addr,!1,t)}function ub(i,e){let t=ao(e,this.size,9);i.uniformMatrix3fv(this.addr,!1,t)}function db(i,e){let t=ao(e,this.size,16);i.uniformMatrix4fv(this.addr,!1,t)}function fb(i,e){i.uniform1iv(this.addr,e)}function pb(i,e){i.uniform2iv(this.addr,e)}function mb(i,e){i.uniform3iv(this.addr,e)}function gb(i,e){i.uniform4iv(this.addr,e)}function _b(i,e){i.uniform1uiv(this.addr,e)}function xb(i,e){i.uniform2uiv(this.addr,e)}function vb(i,e){i.uniform3uiv(this.addr,e)}function yb(i,e){i.uniform4uiv(this.addr,e)}function bb(i,e,t){let n=this.cache,s=e.length,r=Gc(t,s);mn(n,r)||(i.uniform1iv(this.addr,r),gn(n,r));let o;this.type===i.SAMPLER_2D_SHADOW?o=Wc(am):o=om;for(let a=0;a!==s;++a)t.setTexture2D(e[a]||o,r[a])}function Sb(i,e,t){let n=this.cache,s=e.length,r=Gc(t,s);mn(n,r)||(i.uniform1iv(this.addr,r),gn(n,r));for(let o=0;o!==s;++o)t.setTexture3D(e[o]||hm,r[o])}function Mb(i,e,t){let n=this.cache,s=e.length,r=Gc(t,s);mn(n,r)||(i.uniform1iv(this.addr,r),gn(n,r));let o;this.type===i.SAMPLER_CUBE_SHADOW?o=Wc(lm):o=um;for(let a=0;a!==s;++a)t.setTextureCube(e[a]||o,r[a])}function wb(i,e,t){let n=this.cache,s=e.length,r=Gc(t,s);mn(n,r)||(i.uniform1iv(this.addr,r),gn(n,r));for(let o=0;o!==s;++o)t.setTexture2DArray(e[o]||cm,r[o])}function Eb(i){switch(i){case 5126:return ob;case 35664:return ab;case 35665:return lb;case 35666:return cb;case 35674:return hb;case 35675:return ub;case 35676:return db;case 5124:case 35670:return fb;case 35667:case 35671:return pb;case 35668:case 35672:return mb;case 35669:case 35673:return gb;case 5125:return _b;case 36294:return xb;case 36295:return vb;case 36296:return yb;case 35678:case 36198:case 36298:case 36306:case 35682:return bb;case 35679:case 36299:case 36307:return Sb;case 35680:case 36300:case 36308:case 36293:return Mb;case 36289:case 36303:case 36311:case 36292:return wb}}var Zu=class{constructor(e,t,n){this.id=e,this.addr=n,this.cache=[],this.type=t.type,this.setValue=rb(t.type)}},Ju=class{constructor(e,t,n){this.id=e,this.addr=n,this.cache=[],this.type=t.type,this.size=t.size,this.setValue=Eb(t.type)}},Ku=class{constructor(e){this.id=e,this.seq=[],this.map={}}setValue(e,t,n){let s=this.seq;for(let r=0,o=s.length;r!==o;++r){let a=s[r];a.setValue(e,t[a.id],n)}}},qu=/(\w+)(\])?(\[|\.)?/g;function Wp(i,e){i.seq.push(e),i.map[e.id]=e}function Tb(i,e,t){let n=i.name,s=n.length;for(qu.lastIndex=0;;){let r=qu.exec(n),o=qu.lastIndex,a=r[1],c=r[2]==="]",l=r[3];if(c&&(a=a|0),l===void 0||l==="["&&o+2===s){Wp(t,l===void 0?new Zu(a,i,e):new Ju(a,i,e));break}else{let u=t.map[a];u===void 0&&(u=new Ku(a),Wp(t,u)),t=u}}}var oo=class{constructor(e,t){this.seq=[],this.map={};let n=e.getProgramParameter(t,e.ACTIVE_UNIFORMS);for(let o=0;o<n;++o){let a=e.getActiveUniform(t,o),c=e.getUniformLocation(t,a.name);Tb(a,c,this)}let s=[],r=[];for(let o of this.seq)o.type===e.SAMPLER_2D_SHADOW||o.type===e.SAMPLER_CUBE_SHADOW||o.type===e.SAMPLER_2D_ARRAY_SHADOW?s.push(o):r.push(o);s.length>0&&(this.seq=s.concat(r))}setValue(e,t,n,s){let r=this.map[t];r!==void 0&&r.setValue(e,n,s)}setOptional(e,t,n){let s=t[n];s!==void 0&&this.setValue(e,n,s)}static upload(e,t,n,s){for(let r=0,o=t.length;r!==o;++r){let a=t[r],c=n[a.id];c.needsUpdate!==!1&&a.setValue(e,c.value,s)}}static seqWithValue(e,t){let n=[];for(let s=0,r=e.length;s!==r;++s){let o=e[s];o.id in t&&n.push(o)}return n}};function $p(i,e,t){let n=i.createShader(e);return i.shaderSource(n,t),i.compileShader(n),n}var Ab=37297,Rb=0;function Cb(i,e){let t=i.split(`
`),n=[],s=Math.max(e-6,0),r=Math.min(e+6,t.length);for(let o=s;o<r;o++){let a=o+1;n.push(`${a===e?">":" "} ${a}: ${t[o]}`)}return n.join(`
`)}var Xp=new st;function Pb(i){_t._getMatrix(Xp,_t.workingColorSpace,i);let e=`mat3( ${Xp.elements.map(t=>t.toFixed(4))} )`;switch(_t.getTransfer(i)){case Xo:return[e,"LinearTransferOETF"];case Rt:return[e,"sRGBTransferOETF"];default:return Ye("WebGLProgram: Unsupported color space: ",i),[e,"LinearTransferOETF"]}}function qp(i,e,t){let n=i.getShaderParameter(e,i.COMPILE_STATUS),r=(i.getShaderInfoLog(e)||"").trim();if(n&&r==="")return"";let o=/ERROR: 0:(\d+)/.exec(r);if(o){let a=parseInt(o[1]);return t.toUpperCase()+`

`+r+`

`+Cb(i.getShaderSource(e),a)}else return r}function Ib(i,e){let t=Pb(e);return[`vec4 ${i}( vec4 value ) {`,`	return ${t[1]}( vec4( ${t[0]} * value.rgb, value.a ) );`,"}"].join(`
`)}var Lb={[pu]:"Linear",[mu]:"Reinhard",[gu]:"Cineon",[_u]:"ACESFilmic",[vu]:"AgX",[yu]:"Neutral",[xu]:"Custom"};function Db(i,e){let t=Lb[e];return t===void 0?(Ye("WebGLProgram: Unsupported toneMapping:",e),"vec3 "+i+"( vec3 color ) { return LinearToneMapping( color ); }"):"vec3 "+i+"( vec3 color ) { return "+t+"ToneMapping( color ); }"}var zc=new W;function Nb(){_t.getLuminanceCoefficients(zc);let i=zc.x.toFixed(4),e=zc.y.toFixed(4),t=zc.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${i}, ${e}, ${t} );`,"	return dot( weights, rgb );","}"].join(`
`)}function Ub(i){return[i.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",i.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(Pa).join(`
`)}function Fb(i){let e=[];for(let t in i){let n=i[t];n!==!1&&e.push("#define "+t+" "+n)}return e.join(`
`)}function Ob(i,e){let t={},n=i.getProgramParameter(e,i.ACTIVE_ATTRIBUTES);for(let s=0;s<n;s++){let r=i.getActiveAttrib(e,s),o=r.name,a=1;r.type===i.FLOAT_MAT2&&(a=2),r.type===i.FLOAT_MAT3&&(a=3),r.type===i.FLOAT_MAT4&&(a=4),t[o]={type:r.type,location:i.getAttribLocation(e,o),locationSize:a}}return t}function Pa(i){return i!==""}function Yp(i,e){let t=e.numSpotLightShadows+e.numSpotLightMaps-e.numSpotLightShadowsWithMaps;return i.replace(/NUM_SUN_LIGHTS/g,e.numSunLights).replace(/NUM_DIR_LIGHTS/g,e.numDirLights).replace(/NUM_SPOT_LIGHTS/g,e.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,e.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,t).replace(/NUM_RECT_AREA_LIGHTS/g,e.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,e.numPointLights).replace(/NUM_HEMI_LIGHTS/g,e.numHemiLights).replace(/NUM_SUN_LIGHT_SHADOWS/g,e.numSunLightShadows).replace(/NUM_DIR_LIGHT_SHADOWS/g,e.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,e.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,e.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,e.numPointLightShadows).replace(/NUM_LIGHT_PROBE_GRIDS/g,e.numLightProbeGrids)}function Zp(i,e){return i.replace(/NUM_CLIPPING_PLANES/g,e.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,e.numClippingPlanes-e.numClipIntersection)}var Bb=/^[ \t]*#include +<([\w\d./]+)>/gm;function ju(i){return i.replace(Bb,kb)}function kb(i,e){let t=dt[e];if(t===void 0)throw new Error("THREE.WebGLProgram: Can not resolve #include <"+e+">");return ju(t)}var zb=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;function Jp(i){return i.replace(zb,Vb)}function Vb(i,e,t,n){let s="";for(let r=parseInt(e);r<parseInt(t);r++)s+=n.replace(/\[\s*i\s*\]/g,"[ "+r+" ]").replace(/UNROLLED_LOOP_INDEX/g,r);return s}function Kp(i){let e=`precision ${i.precision} float;
	precision ${i.precision} int;
	precision ${i.precision} sampler2D;
	precision ${i.precision} samplerCube;
	precision ${i.precision} sampler3D;
	precision ${i.precision} sampler2DArray;
	precision ${i.precision} sampler2DShadow;
	precision ${i.precision} samplerCubeShadow;
	precision ${i.precision} sampler2DArrayShadow;
	precision ${i.precision} isampler2D;
	precision ${i.precision} isampler3D;
	precision ${i.precision} isamplerCube;
	precision ${i.precision} isampler2DArray;
	precision ${i.precision} usampler2D;
	precision ${i.precision} usampler3D;
	precision ${i.precision} usamplerCube;
	precision ${i.precision} usampler2DArray;
	`;return i.precision==="highp"?e+=`
#define HIGH_PRECISION`:i.precision==="mediump"?e+=`
#define MEDIUM_PRECISION`:i.precision==="lowp"&&(e+=`
#define LOW_PRECISION`),e}var Hb={[va]:"SHADOWMAP_TYPE_PCF",[no]:"SHADOWMAP_TYPE_VSM"};function Gb(i){return Hb[i.shadowMapType]||"SHADOWMAP_TYPE_BASIC"}var Wb={[so]:"ENVMAP_MODE_REFRACTION"};function $b(i){return i.envMap===!1?"ENVMAP_MODE_REFLECTION":Wb[i.envMapMode]||"ENVMAP_MODE_REFLECTION"}var Xb={[fu]:"ENVMAP_BLENDING_MULTIPLY",[_p]:"ENVMAP_BLENDING_MIX",[xp]:"ENVMAP_BLENDING_ADD"};function qb(i){return i.envMap===!1?"ENVMAP_BLENDING_NONE":Xb[i.combine]||"ENVMAP_BLENDING_NONE"}function Yb(i,e,t,n){let s=i.getContext(),r=t.defines,o=t.vertexShader,a=t.fragmentShader,c=Gb(t),l=t.envMapPMREM===!0?"ENVMAP_TYPE_PMREM":"ENVMAP_TYPE_CUBE",d=$b(t),u=qb(t),h=Ub(t),m=Fb(r),g=s.createProgram(),v,p,f=t.glslVersion?"#version "+t.glslVersion+`
`:"";t.isRawShaderMaterial?(v=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m].filter(Pa).join(`
`),v.length>0&&(v+=`
`),p=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m].filter(Pa).join(`
`),p.length>0&&(p+=`
`)):(v=[Kp(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m,t.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",t.batching?"#define USE_BATCHING":"",t.batchingColor?"#define USE_BATCHING_COLOR":"",t.instancing?"#define USE_INSTANCING":"",t.instancingColor?"#define USE_INSTANCING_COLOR":"",t.instancingMorph?"#define USE_INSTANCING_MORPH":"",t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.map?"#define USE_MAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+d:"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.displacementMap?"#define USE_DISPLACEMENTMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.mapUv?"#define MAP_UV "+t.mapUv:"",t.alphaMapUv?"#define ALPHAMAP_UV "+t.alphaMapUv:"",t.lightMapUv?"#define LIGHTMAP_UV "+t.lightMapUv:"",t.aoMapUv?"#define AOMAP_UV "+t.aoMapUv:"",t.emissiveMapUv?"#define EMISSIVEMAP_UV "+t.emissiveMapUv:"",t.bumpMapUv?"#define BUMPMAP_UV "+t.bumpMapUv:"",t.normalMapUv?"#define NORMALMAP_UV "+t.normalMapUv:"",t.displacementMapUv?"#define DISPLACEMENTMAP_UV "+t.displacementMapUv:"",t.metalnessMapUv?"#define METALNESSMAP_UV "+t.metalnessMapUv:"",t.roughnessMapUv?"#define ROUGHNESSMAP_UV "+t.roughnessMapUv:"",t.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+t.anisotropyMapUv:"",t.clearcoatMapUv?"#define CLEARCOATMAP_UV "+t.clearcoatMapUv:"",t.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+t.clearcoatNormalMapUv:"",t.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+t.clearcoatRoughnessMapUv:"",t.diffuseRoughnessMapUv?"#define DIFFUSE_ROUGHNESSMAP_UV "+t.diffuseRoughnessMapUv:"",t.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+t.iridescenceMapUv:"",t.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+t.iridescenceThicknessMapUv:"",t.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+t.sheenColorMapUv:"",t.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+t.sheenRoughnessMapUv:"",t.specularMapUv?"#define SPECULARMAP_UV "+t.specularMapUv:"",t.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+t.specularColorMapUv:"",t.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+t.specularIntensityMapUv:"",t.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+t.transmissionMapUv:"",t.thicknessMapUv?"#define THICKNESSMAP_UV "+t.thicknessMapUv:"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexNormals?"#define HAS_NORMAL":"",t.vertexColors?"#define USE_COLOR":"",t.vertexAlphas?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.flatShading?"#define FLAT_SHADED":"",t.skinning?"#define USE_SKINNING":"",t.morphTargets?"#define USE_MORPHTARGETS":"",t.morphNormals&&t.flatShading===!1?"#define USE_MORPHNORMALS":"",t.morphColors?"#define USE_MORPHCOLORS":"",t.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+t.morphTextureStride:"",t.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+t.morphTargetsCount:"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+c:"",t.sizeAttenuation?"#define USE_SIZEATTENUATION":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(Pa).join(`
`),p=[Kp(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,m,t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",t.map?"#define USE_MAP":"",t.matcap?"#define USE_MATCAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+l:"",t.envMap?"#define "+d:"",t.envMap?"#define "+u:"",t.envMapPMREM?"#define ENVMAP_MAX_LOD "+t.envMapMaxLod+".0":"",t.envMapPMREM?"#define ENVMAP_SIZE "+t.envMapSize+".0":"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.packedNormalMap?"#define USE_PACKED_NORMALMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoat?"#define USE_CLEARCOAT":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughness?"#define USE_DIFFUSE_ROUGHNESS":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.dispersion?"#define USE_DISPERSION":"",t.retroreflection?"#define USE_RETROREFLECTION":"",t.iridescence?"#define USE_IRIDESCENCE":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaTest?"#define USE_ALPHATEST":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.sheen?"#define USE_SHEEN":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexColors||t.instancingColor?"#define USE_COLOR":"",t.vertexAlphas||t.batchingColor?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.gradientMap?"#define USE_GRADIENTMAP":"",t.flatShading?"#define FLAT_SHADED":"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+c:"",t.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",t.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",t.toneMapping!==Ji?"#define TONE_MAPPING":"",t.toneMapping!==Ji?dt.tonemapping_pars_fragment:"",t.toneMapping!==Ji?Db("toneMapping",t.toneMapping):"",t.dithering?"#define DITHERING":"",t.opaque?"#define OPAQUE":"",dt.colorspace_pars_fragment,Ib("linearToOutputTexel",t.outputColorSpace),Nb(),t.useDepthPacking?"#define DEPTH_PACKING "+t.depthPacking:"",`
`].filter(Pa).join(`
`)),o=ju(o),o=Yp(o,t),o=Zp(o,t),a=ju(a),a=Yp(a,t),a=Zp(a,t),o=Jp(o),a=Jp(a),t.isRawShaderMaterial!==!0&&(f=`#version 300 es
`,v=[h,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+v,p=["#define varying in",t.glslVersion===Du?"":"layout(location = 0) out highp vec4 pc_fragColor;",t.glslVersion===Du?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+p);let y=f+v+o,C=f+p+a,M=$p(s,s.VERTEX_SHADER,y),R=$p(s,s.FRAGMENT_SHADER,C);s.attachShader(g,M),s.attachShader(g,R),t.index0AttributeName!==void 0?s.bindAttribLocation(g,0,t.index0AttributeName):t.hasPositionAttribute===!0&&s.bindAttribLocation(g,0,"position"),s.linkProgram(g);function b(O){if(i.debug.checkShaderErrors){let T=s.getProgramInfoLog(g)||"",F=s.getShaderInfoLog(M)||"",B=s.getShaderInfoLog(R)||"",D=T.trim(),V=F.trim(),Y=B.trim(),$=!0,ce=!0;if(s.getProgramParameter(g,s.LINK_STATUS)===!1)if($=!1,typeof i.debug.onShaderError=="function")i.debug.onShaderError(s,g,M,R);else{let P=qp(s,M,"vertex"),I=qp(s,R,"fragment");it("WebGLProgram: Shader Error "+s.getError()+" - VALIDATE_STATUS "+s.getProgramParameter(g,s.VALIDATE_STATUS)+`

Material Name: `+O.name+`
Material Type: `+O.type+`

Program Info Log: `+D+`
`+P+`
`+I)}else D!==""?Ye("WebGLProgram: Program Info Log:",D):(V===""||Y==="")&&(ce=!1);ce&&(O.diagnostics={runnable:$,programLog:D,vertexShader:{log:V,prefix:v},fragmentShader:{log:Y,prefix:p}})}s.deleteShader(M),s.deleteShader(R),_=new oo(s,g),A=Ob(s,g)}let _;this.getUniforms=function(){return _===void 0&&b(this),_};let A;this.getAttributes=function(){return A===void 0&&b(this),A};let H=t.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return H===!1&&(H=s.getProgramParameter(g,Ab)),H},this.destroy=function(){n.releaseStatesOfProgram(this),s.deleteProgram(g),this.program=void 0},this.type=t.shaderType,this.name=t.shaderName,this.id=Rb++,this.cacheKey=e,this.usedTimes=1,this.program=g,this.vertexShader=M,this.fragmentShader=R,this}var Zb=0,Qu=class{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(e,t,n){let s=this._getShaderCacheForMaterial(e);return s.has(t)===!1&&(s.add(t),t.usedTimes++),s.has(n)===!1&&(s.add(n),n.usedTimes++),this}remove(e){let t=this.materialCache.get(e);for(let n of t)n.usedTimes--,n.usedTimes===0&&this.shaderCache.delete(n.code);return this.materialCache.delete(e),this}getVertexShaderStage(e){return this._getShaderStage(e.vertexShader)}getFragmentShaderStage(e){return this._getShaderStage(e.fragmentShader)}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(e){let t=this.materialCache,n=t.get(e);return n===void 0&&(n=new Set,t.set(e,n)),n}_getShaderStage(e){let t=this.shaderCache,n=t.get(e);return n===void 0&&(n=new ed(e),t.set(e,n)),n}},ed=class{constructor(e){this.id=Zb++,this.code=e,this.usedTimes=0}};function Jb(i){return i===$s||i===Ea||i===Ta}function Kb(i,e,t,n,s,r){let o=new Jo,a=new Qu,c=new Set,l=[],d=new Map,u=n.logarithmicDepthBuffer,h={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distance",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function m(_){return c.add(_),_===0?"uv":`uv${_}`}function g(_,A,H,O,T,F){let B=O.fog,D=T.geometry,V=_.isMeshStandardMaterial||_.isMeshLambertMaterial||_.isMeshPhongMaterial?O.environment:null,Y=_.isMeshStandardMaterial||_.isMeshLambertMaterial&&!_.envMap||_.isMeshPhongMaterial&&!_.envMap,$=e.get(_.envMap||V,Y),ce=h[_.type],P=n.precision;_.precision!==null&&(P=n.getMaxPrecision(_.precision),P!==_.precision&&Ye("WebGLProgram.getParameters:",_.precision,"not supported, using",P,"instead."));let I=D.morphAttributes.position||D.morphAttributes.normal||D.morphAttributes.color,q=I!==void 0?I.length:0,ie=0;D.morphAttributes.position!==void 0&&(ie=1),D.morphAttributes.normal!==void 0&&(ie=2),D.morphAttributes.color!==void 0&&(ie=3);let he,Q,fe,le;if(ce){let Ae=Zn[ce];he=Ae.vertexShader,Q=Ae.fragmentShader}else{he=_.vertexShader,Q=_.fragmentShader;let Ae=a.getVertexShaderStage(_),ht=a.getFragmentShaderStage(_);a.update(_,Ae,ht),fe=Ae.id,le=ht.id}let me=i.getRenderTarget(),pe=i.state.buffers.depth.getReversed(),De=T.isInstancedMesh===!0,Ze=T.isBatchedMesh===!0,Ne=!!_.map,qe=!!_.matcap,ot=!!$,Qe=ot&&$.isPMREMTexture===!0,bt=!!_.aoMap,At=!!_.lightMap,sn=!!_.bumpMap&&_.wireframe===!1,Nt=!!_.normalMap,yn=!!_.displacementMap,yt=!!_.emissiveMap,fn=!!_.metalnessMap,Jt=!!_.roughnessMap,rn=_.anisotropy>0,z=_.clearcoat>0,Re=_.diffuseRoughness>0,Je=_.dispersion>0,at=_.retroreflectivity>0,Me=_.iridescence>0,Bt=_.sheen>0,He=_.transmission>0,$e=rn&&!!_.anisotropyMap,L=z&&!!_.clearcoatMap,S=z&&!!_.clearcoatNormalMap,Z=z&&!!_.clearcoatRoughnessMap,de=Re&&!!_.diffuseRoughnessMap,oe=Me&&!!_.iridescenceMap,ve=Me&&!!_.iridescenceThicknessMap,ye=Bt&&!!_.sheenColorMap,te=Bt&&!!_.sheenRoughnessMap,se=!!_.specularMap,_e=!!_.specularColorMap,k=!!_.specularIntensityMap,re=He&&!!_.transmissionMap,ne=He&&!!_.thicknessMap,we=!!_.gradientMap,xe=!!_.alphaMap,Se=_.alphaTest>0,Ge=!!_.alphaHash,et=!!_.extensions,ue=Ji;_.toneMapped&&(me===null||me.isXRRenderTarget===!0)&&(ue=i.toneMapping);let ke=Qe?$.isCompressedCubeTexture?$.image[0].mipmaps:$.mipmaps:null,tt={shaderID:ce,shaderType:_.type,shaderName:_.name,vertexShader:he,fragmentShader:Q,defines:_.defines,customVertexShaderID:fe,customFragmentShaderID:le,isRawShaderMaterial:_.isRawShaderMaterial===!0,glslVersion:_.glslVersion,precision:P,batching:Ze,batchingColor:Ze&&T._colorsTexture!==null,instancing:De,instancingColor:De&&T.instanceColor!==null,instancingMorph:De&&T.morphTexture!==null,outputColorSpace:me===null?i.outputColorSpace:me.isXRRenderTarget===!0?me.texture.colorSpace:_t.workingColorSpace,alphaToCoverage:!!_.alphaToCoverage,map:Ne,matcap:qe,envMap:ot,envMapMode:ot&&$.mapping,envMapPMREM:Qe,envMapMaxLod:Qe?ke.length-1:null,envMapSize:Qe?ke[0].width:null,aoMap:bt,lightMap:At,bumpMap:sn,normalMap:Nt,displacementMap:yn,emissiveMap:yt,normalMapObjectSpace:Nt&&_.normalMapType===bp,normalMapTangentSpace:Nt&&_.normalMapType===Oc,packedNormalMap:Nt&&_.normalMapType===Oc&&Jb(_.normalMap.format),metalnessMap:fn,roughnessMap:Jt,anisotropy:rn,anisotropyMap:$e,clearcoat:z,clearcoatMap:L,clearcoatNormalMap:S,clearcoatRoughnessMap:Z,diffuseRoughness:Re,diffuseRoughnessMap:de,dispersion:Je,retroreflection:at,iridescence:Me,iridescenceMap:oe,iridescenceThicknessMap:ve,sheen:Bt,sheenColorMap:ye,sheenRoughnessMap:te,specularMap:se,specularColorMap:_e,specularIntensityMap:k,transmission:He,transmissionMap:re,thicknessMap:ne,gradientMap:we,opaque:_.transparent===!1&&_.blending===io&&_.alphaToCoverage===!1,alphaMap:xe,alphaTest:Se,alphaHash:Ge,combine:_.combine,mapUv:Ne&&m(_.map.channel),aoMapUv:bt&&m(_.aoMap.channel),lightMapUv:At&&m(_.lightMap.channel),bumpMapUv:sn&&m(_.bumpMap.channel),normalMapUv:Nt&&m(_.normalMap.channel),displacementMapUv:yn&&m(_.displacementMap.channel),emissiveMapUv:yt&&m(_.emissiveMap.channel),metalnessMapUv:fn&&m(_.metalnessMap.channel),roughnessMapUv:Jt&&m(_.roughnessMap.channel),anisotropyMapUv:$e&&m(_.anisotropyMap.channel),clearcoatMapUv:L&&m(_.clearcoatMap.channel),clearcoatNormalMapUv:S&&m(_.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:Z&&m(_.clearcoatRoughnessMap.channel),diffuseRoughnessMapUv:de&&m(_.diffuseRoughnessMap.channel),iridescenceMapUv:oe&&m(_.iridescenceMap.channel),iridescenceThicknessMapUv:ve&&m(_.iridescenceThicknessMap.channel),sheenColorMapUv:ye&&m(_.sheenColorMap.channel),sheenRoughnessMapUv:te&&m(_.sheenRoughnessMap.channel),specularMapUv:se&&m(_.specularMap.channel),specularColorMapUv:_e&&m(_.specularColorMap.channel),specularIntensityMapUv:k&&m(_.specularIntensityMap.channel),transmissionMapUv:re&&m(_.transmissionMap.channel),thicknessMapUv:ne&&m(_.thicknessMap.channel),alphaMapUv:xe&&m(_.alphaMap.channel),vertexTangents:!!D.attributes.tangent&&(Nt||rn),vertexNormals:!!D.attributes.normal,vertexColors:_.vertexColors,vertexAlphas:_.vertexColors===!0&&!!D.attributes.color&&D.attributes.color.itemSize===4,pointsUvs:T.isPoints===!0&&!!D.attributes.uv&&(Ne||xe),fog:!!B,useFog:_.fog===!0,fogExp2:!!B&&B.isFogExp2,flatShading:_.wireframe===!1&&(_.flatShading===!0||D.attributes.normal===void 0&&Nt===!1&&(_.isMeshLambertMaterial||_.isMeshPhongMaterial||_.isMeshStandardMaterial||_.isMeshPhysicalMaterial)),sizeAttenuation:_.sizeAttenuation===!0,logarithmicDepthBuffer:u,reversedDepthBuffer:pe,skinning:T.isSkinnedMesh===!0,hasPositionAttribute:D.attributes.position!==void 0,morphTargets:D.morphAttributes.position!==void 0,morphNormals:D.morphAttributes.normal!==void 0,morphColors:D.morphAttributes.color!==void 0,morphTargetsCount:q,morphTextureStride:ie,numSunLights:A.sun.length,numDirLights:A.directional.length,numPointLights:A.point.length,numSpotLights:A.spot.length,numSpotLightMaps:A.spotLightMap.length,numRectAreaLights:A.rectArea.length,numHemiLights:A.hemi.length,numSunLightShadows:A.sunShadowMap.length,numDirLightShadows:A.directionalShadowMap.length,numPointLightShadows:A.pointShadowMap.length,numSpotLightShadows:A.spotShadowMap.length,numSpotLightShadowsWithMaps:A.numSpotLightShadowsWithMaps,numLightProbes:A.numLightProbes,numLightProbeGrids:F.filter(Ae=>Ae.texture!==null).length,numClippingPlanes:r.numPlanes,numClipIntersection:r.numIntersection,dithering:_.dithering,shadowMapEnabled:i.shadowMap.enabled&&H.length>0,shadowMapType:i.shadowMap.type,toneMapping:ue,decodeVideoTexture:Ne&&_.map.isVideoTexture===!0&&_t.getTransfer(_.map.colorSpace)===Rt,decodeVideoTextureEmissive:yt&&_.emissiveMap.isVideoTexture===!0&&_t.getTransfer(_.emissiveMap.colorSpace)===Rt,premultipliedAlpha:_.premultipliedAlpha,doubleSided:_.side===Zi,flipSided:_.side===Yn,useDepthPacking:_.depthPacking>=0,depthPacking:_.depthPacking||0,index0AttributeName:_.index0AttributeName,extensionClipCullDistance:et&&_.extensions.clipCullDistance===!0&&t.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(et&&_.extensions.multiDraw===!0||Ze)&&t.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:t.has("KHR_parallel_shader_compile"),customProgramCacheKey:_.customProgramCacheKey()};return tt.vertexUv1s=c.has(1),tt.vertexUv2s=c.has(2),tt.vertexUv3s=c.has(3),c.clear(),tt}function v(_){let A=[];if(_.shaderID?A.push(_.shaderID):(A.push(_.customVertexShaderID),A.push(_.customFragmentShaderID)),_.defines!==void 0)for(let H in _.defines)A.push(H),A.push(_.defines[H]);return _.isRawShaderMaterial===!1&&(p(A,_),f(A,_),A.push(i.outputColorSpace)),A.push(_.customProgramCacheKey),A.join()}function p(_,A){_.push(A.precision),_.push(A.outputColorSpace),_.push(A.envMapMode),_.push(A.envMapPMREM),_.push(A.envMapMaxLod),_.push(A.envMapSize),_.push(A.mapUv),_.push(A.alphaMapUv),_.push(A.lightMapUv),_.push(A.aoMapUv),_.push(A.bumpMapUv),_.push(A.normalMapUv),_.push(A.displacementMapUv),_.push(A.emissiveMapUv),_.push(A.metalnessMapUv),_.push(A.roughnessMapUv),_.push(A.anisotropyMapUv),_.push(A.clearcoatMapUv),_.push(A.clearcoatNormalMapUv),_.push(A.clearcoatRoughnessMapUv),_.push(A.diffuseRoughnessMapUv),_.push(A.iridescenceMapUv),_.push(A.iridescenceThicknessMapUv),_.push(A.sheenColorMapUv),_.push(A.sheenRoughnessMapUv),_.push(A.specularMapUv),_.push(A.specularColorMapUv),_.push(A.specularIntensityMapUv),_.push(A.transmissionMapUv),_.push(A.thicknessMapUv),_.push(A.combine),_.push(A.fogExp2),_.push(A.sizeAttenuation),_.push(A.morphTargetsCount),_.push(A.numSunLights),_.push(A.numDirLights),_.push(A.numPointLights),_.push(A.numSpotLights),_.push(A.numSpotLightMaps),_.push(A.numHemiLights),_.push(A.numRectAreaLights),_.push(A.numSunLightShadows),_.push(A.numDirLightShadows),_.push(A.numPointLightShadows),_.push(A.numSpotLightShadows),_.push(A.numSpotLightShadowsWithMaps),_.push(A.numLightProbes),_.push(A.numLightProbeGrids),_.push(A.shadowMapType),_.push(A.toneMapping),_.push(A.numClippingPlanes),_.push(A.numClipIntersection),_.push(A.depthPacking)}function f(_,A){o.disableAll(),A.instancing&&o.enable(0),A.instancingColor&&o.enable(1),A.instancingMorph&&o.enable(2),A.matcap&&o.enable(3),A.envMap&&o.enable(4),A.normalMapObjectSpace&&o.enable(5),A.normalMapTangentSpace&&o.enable(6),A.clearcoat&&o.enable(7),A.iridescence&&o.enable(8),A.alphaTest&&o.enable(9),A.vertexColors&&o.enable(10),A.vertexAlphas&&o.enable(11),A.vertexUv1s&&o.enable(12),A.vertexUv2s&&o.enable(13),A.vertexUv3s&&o.enable(14),A.vertexTangents&&o.enable(15),A.anisotropy&&o.enable(16),A.alphaHash&&o.enable(17),A.batching&&o.enable(18),A.dispersion&&o.enable(19),A.retroreflection&&o.enable(24),A.diffuseRoughness&&o.enable(25),A.batchingColor&&o.enable(20),A.gradientMap&&o.enable(21),A.packedNormalMap&&o.enable(22),A.vertexNormals&&o.enable(23),_.push(o.mask),o.disableAll(),A.fog&&o.enable(0),A.useFog&&o.enable(1),A.flatShading&&o.enable(2),A.logarithmicDepthBuffer&&o.enable(3),A.reversedDepthBuffer&&o.enable(4),A.skinning&&o.enable(5),A.morphTargets&&o.enable(6),A.morphNormals&&o.enable(7),A.morphColors&&o.enable(8),A.premultipliedAlpha&&o.enable(9),A.shadowMapEnabled&&o.enable(10),A.doubleSided&&o.enable(11),A.flipSided&&o.enable(12),A.useDepthPacking&&o.enable(13),A.dithering&&o.enable(14),A.transmission&&o.enable(15),A.sheen&&o.enable(16),A.opaque&&o.enable(17),A.pointsUvs&&o.enable(18),A.decodeVideoTexture&&o.enable(19),A.decodeVideoTextureEmissive&&o.enable(20),A.alphaToCoverage&&o.enable(21),A.numLightProbeGrids>0&&o.enable(22),A.hasPositionAttribute&&o.enable(23),_.push(o.mask)}function y(_){let A=h[_.type],H;if(A){let O=Zn[A];H=Ra.clone(O.uniforms)}else H=_.uniforms;return H}function C(_,A){let H=d.get(A);return H!==void 0?++H.usedTimes:(H=new Yb(i,A,_,s),l.push(H),d.set(A,H)),H}function M(_){if(--_.usedTimes===0){let A=l.indexOf(_);l[A]=l[l.length-1],l.pop(),d.delete(_.cacheKey),_.destroy()}}function R(_){a.remove(_)}function b(){a.dispose()}return{getParameters:g,getProgramCacheKey:v,getUniforms:y,acquireProgram:C,releaseProgram:M,releaseShaderCache:R,programs:l,dispose:b}}function jb(){let i=new WeakMap;function e(o){return i.has(o)}function t(o){let a=i.get(o);return a===void 0&&(a={},i.set(o,a)),a}function n(o){i.delete(o)}function s(o,a,c){i.get(o)[a]=c}function r(){i=new WeakMap}return{has:e,get:t,remove:n,update:s,dispose:r}}function Qb(i,e){return i.groupOrder!==e.groupOrder?i.groupOrder-e.groupOrder:i.renderOrder!==e.renderOrder?i.renderOrder-e.renderOrder:i.material.id!==e.material.id?i.material.id-e.material.id:i.materialVariant!==e.materialVariant?i.materialVariant-e.materialVariant:i.z!==e.z?i.z-e.z:i.id-e.id}function jp(i,e){return i.groupOrder!==e.groupOrder?i.groupOrder-e.groupOrder:i.renderOrder!==e.renderOrder?i.renderOrder-e.renderOrder:i.z!==e.z?e.z-i.z:i.id-e.id}function Qp(){let i=[],e=0,t=[],n=[],s=[];function r(){e=0,t.length=0,n.length=0,s.length=0}function o(h){let m=0;return h.isInstancedMesh&&(m+=2),h.isSkinnedMesh&&(m+=1),m}function a(h,m,g,v,p,f){let y=i[e];return y===void 0?(y={id:h.id,object:h,geometry:m,material:g,materialVariant:o(h),groupOrder:v,renderOrder:h.renderOrder,z:p,group:f},i[e]=y):(y.id=h.id,y.object=h,y.geometry=m,y.material=g,y.materialVariant=o(h),y.groupOrder=v,y.renderOrder=h.renderOrder,y.z=p,y.group=f),e++,y}function c(h,m,g,v,p,f,y){y.reversedDepth===!0&&(p=-p);let C=a(h,m,g,v,p,f);g.transmission>0?n.push(C):g.transparent===!0?s.push(C):t.push(C)}function l(h,m,g,v,p,f){let y=a(h,m,g,v,p,f);g.transmission>0?n.unshift(y):g.transparent===!0?s.unshift(y):t.unshift(y)}function d(h,m){t.length>1&&t.sort(h||Qb),n.length>1&&n.sort(m||jp),s.length>1&&s.sort(m||jp)}function u(){for(let h=e,m=i.length;h<m;h++){let g=i[h];if(g.id===null)break;g.id=null,g.object=null,g.geometry=null,g.material=null,g.group=null}}return{opaque:t,transmissive:n,transparent:s,init:r,push:c,unshift:l,finish:u,sort:d}}function eS(){let i=new WeakMap;function e(n,s){let r=i.get(n),o;return r===void 0?(o=new Qp,i.set(n,[o])):s>=r.length?(o=new Qp,r.push(o)):o=r[s],o}function t(){i=new WeakMap}return{get:e,dispose:t}}function tS(){let i={};return{get:function(e){if(i[e.id]!==void 0)return i[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={direction:new W,color:new ct};break;case"SpotLight":t={position:new W,direction:new W,color:new ct,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":t={position:new W,color:new ct,distance:0,decay:0};break;case"HemisphereLight":t={direction:new W,skyColor:new ct,groundColor:new ct};break;case"RectAreaLight":t={color:new ct,position:new W,halfWidth:new W,halfHeight:new W};break}return i[e.id]=t,t}}}function nS(){let i={};return{get:function(e){if(i[e.id]!==void 0)return i[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new je};break;case"SpotLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new je};break;case"PointLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new je,shadowCameraNear:1,shadowCameraFar:1e3};break}return i[e.id]=t,t}}}var iS=0;function sS(i,e){return(e.castShadow?2:0)-(i.castShadow?2:0)+(e.map?1:0)-(i.map?1:0)}function rS(i){let e=new tS,t=nS(),n={version:0,hash:{sunLength:-1,directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numSunShadows:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],sun:[],sunShadow:[],sunShadowMap:[],sunShadowMatrix:[],sunShadowCascade:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let l=0;l<9;l++)n.probe.push(new W);let s=new W,r=new kt,o=new kt;function a(l){let d=0,u=0,h=0;for(let F=0;F<9;F++)n.probe[F].set(0,0,0);let m=0,g=0,v=0,p=0,f=0,y=0,C=0,M=0,R=0,b=0,_=0,A=0,H=0,O=0;l.sort(sS);for(let F=0,B=l.length;F<B;F++){let D=l[F],V=D.color,Y=D.intensity,$=D.distance,ce=null;if(D.shadow&&D.shadow.map&&(D.shadow.map.texture.format===$s?ce=D.shadow.map.texture:ce=D.shadow.map.depthTexture||D.shadow.map.texture),D.isAmbientLight)d+=V.r*Y,u+=V.g*Y,h+=V.b*Y;else if(D.isLightProbe){for(let P=0;P<9;P++)n.probe[P].addScaledVector(D.sh.coefficients[P],Y);O++}else if(D.isSunLight){let P=e.get(D);if(P.color.copy(D.color).multiplyScalar(D.intensity),D.castShadow){let I=D.shadow,q=t.get(D);q.shadowIntensity=I.intensity,q.shadowBias=I.bias,q.shadowNormalBias=I.normalBias,q.shadowRadius=I.radius,q.shadowMapSize.copy(I.mapSize).multiply(I.getFrameExtents()),n.sunShadow[g]=q,n.sunShadowMap[g]=ce;let ie=I.getViewportCount();for(let he=0;he<ie;he++)n.sunShadowMatrix[v+he]=I.getMatrix(he),n.sunShadowCascade[v+he]=I._cascadeData[he];v+=ie,g++}n.sun[m]=P,m++}else if(D.isDirectionalLight){let P=e.get(D);if(P.color.copy(D.color).multiplyScalar(D.intensity),D.castShadow){let I=D.shadow,q=t.get(D);q.shadowIntensity=I.intensity,q.shadowBias=I.bias,q.shadowNormalBias=I.normalBias,q.shadowRadius=I.radius,q.shadowMapSize=I.mapSize,n.directionalShadow[p]=q,n.directionalShadowMap[p]=ce,n.directionalShadowMatrix[p]=D.shadow.matrix,R++}n.directional[p]=P,p++}else if(D.isSpotLight){let P=e.get(D);P.position.setFromMatrixPosition(D.matrixWorld),P.color.copy(V).multiplyScalar(Y),P.distance=$,P.coneCos=Math.cos(D.angle),P.penumbraCos=Math.cos(D.angle*(1-D.penumbra)),P.decay=D.decay,n.spot[y]=P;let I=D.shadow;if(D.map&&(n.spotLightMap[A]=D.map,A++,I.updateMatrices(D),D.castShadow&&H++),n.spotLightMatrix[y]=I.matrix,D.castShadow){let q=t.get(D);q.shadowIntensity=I.intensity,q.shadowBias=I.bias,q.shadowNormalBias=I.normalBias,q.shadowRadius=I.radius,q.shadowMapSize=I.mapSize,n.spotShadow[y]=q,n.spotShadowMap[y]=ce,_++}y++}else if(D.isRectAreaLight){let P=e.get(D);P.color.copy(V).multiplyScalar(Y),P.halfWidth.set(D.width*.5,0,0),P.halfHeight.set(0,D.height*.5,0),n.rectArea[C]=P,C++}else if(D.isPointLight){let P=e.get(D);if(P.color.copy(D.color).multiplyScalar(D.intensity),P.distance=D.distance,P.decay=D.decay,D.castShadow){let I=D.shadow,q=t.get(D);q.shadowIntensity=I.intensity,q.shadowBias=I.bias,q.shadowNormalBias=I.normalBias,q.shadowRadius=I.radius,q.shadowMapSize=I.mapSize,q.shadowCameraNear=I.camera.near,q.shadowCameraFar=I.camera.far,n.pointShadow[f]=q,n.pointShadowMap[f]=ce,n.pointShadowMatrix[f]=D.shadow.matrix,b++}n.point[f]=P,f++}else if(D.isHemisphereLight){let P=e.get(D);P.skyColor.copy(D.color).multiplyScalar(Y),P.groundColor.copy(D.groundColor).multiplyScalar(Y),n.hemi[M]=P,M++}}C>0&&(i.has("OES_texture_float_linear")===!0?(n.rectAreaLTC1=Ce.LTC_FLOAT_1,n.rectAreaLTC2=Ce.LTC_FLOAT_2):(n.rectAreaLTC1=Ce.LTC_HALF_1,n.rectAreaLTC2=Ce.LTC_HALF_2)),n.ambient[0]=d,n.ambient[1]=u,n.ambient[2]=h;let T=n.hash;(T.sunLength!==m||T.directionalLength!==p||T.pointLength!==f||T.spotLength!==y||T.rectAreaLength!==C||T.hemiLength!==M||T.numSunShadows!==g||T.numDirectionalShadows!==R||T.numPointShadows!==b||T.numSpotShadows!==_||T.numSpotMaps!==A||T.numLightProbes!==O)&&(n.sun.length=m,n.directional.length=p,n.spot.length=y,n.rectArea.length=C,n.point.length=f,n.hemi.length=M,n.sunShadow.length=g,n.sunShadowMap.length=g,n.sunShadowMatrix.length=v,n.sunShadowCascade.length=v,n.directionalShadow.length=R,n.directionalShadowMap.length=R,n.directionalShadowMatrix.length=R,n.pointShadow.length=b,n.pointShadowMap.length=b,n.pointShadowMatrix.length=b,n.spotShadow.length=_,n.spotShadowMap.length=_,n.spotLightMatrix.length=_+A-H,n.spotLightMap.length=A,n.numSpotLightShadowsWithMaps=H,n.numLightProbes=O,T.sunLength=m,T.directionalLength=p,T.pointLength=f,T.spotLength=y,T.rectAreaLength=C,T.hemiLength=M,T.numSunShadows=g,T.numDirectionalShadows=R,T.numPointShadows=b,T.numSpotShadows=_,T.numSpotMaps=A,T.numLightProbes=O,n.version=iS++)}function c(l,d){let u=0,h=0,m=0,g=0,v=0,p=0,f=d.matrixWorldInverse;for(let y=0,C=l.length;y<C;y++){let M=l[y];if(M.isSunLight){let R=n.sun[u];R.direction.setFromMatrixPosition(M.matrixWorld),R.direction.transformDirection(f),u++}else if(M.isDirectionalLight){let R=n.directional[h];R.direction.setFromMatrixPosition(M.matrixWorld),s.setFromMatrixPosition(M.target.matrixWorld),R.direction.sub(s),R.direction.transformDirection(f),h++}else if(M.isSpotLight){let R=n.spot[g];R.position.setFromMatrixPosition(M.matrixWorld),R.position.applyMatrix4(f),R.direction.setFromMatrixPosition(M.matrixWorld),s.setFromMatrixPosition(M.target.matrixWorld),R.direction.sub(s),R.direction.transformDirection(f),g++}else if(M.isRectAreaLight){let R=n.rectArea[v];R.position.setFromMatrixPosition(M.matrixWorld),R.position.applyMatrix4(f),o.identity(),r.copy(M.matrixWorld),r.premultiply(f),o.extractRotation(r),R.halfWidth.set(M.width*.5,0,0),R.halfHeight.set(0,M.height*.5,0),R.halfWidth.applyMatrix4(o),R.halfHeight.applyMatrix4(o),v++}else if(M.isPointLight){let R=n.point[m];R.position.setFromMatrixPosition(M.matrixWorld),R.position.applyMatrix4(f),m++}else if(M.isHemisphereLight){let R=n.hemi[p];R.direction.setFromMatrixPosition(M.matrixWorld),R.direction.transformDirection(f),p++}}}return{setup:a,setupView:c,state:n}}function em(i){let e=new rS(i),t=[],n=[],s=[];function r(u){d.camera=u,t.length=0,n.length=0,s.length=0}function o(u){u.isLightProbeGrid?s.push(u):t.push(u)}function a(u){n.push(u)}function c(){e.setup(t),s.sort((u,h)=>u.priority-h.priority||u.id-h.id)}function l(u){e.setupView(t,u)}let d={lightsArray:t,shadowsArray:n,lightProbeGridArray:s,camera:null,lights:e,transmissionRenderTarget:{},textureUnits:0};return{init:r,state:d,setupLights:c,setupLightsView:l,pushLight:o,pushShadow:a}}function oS(i){let e=new WeakMap;function t(s,r=0){let o=e.get(s),a;return o===void 0?(a=new em(i),e.set(s,[a])):r>=o.length?(a=new em(i),o.push(a)):a=o[r],a}function n(){e=new WeakMap}return{get:t,dispose:n}}var aS=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,lS=`uniform sampler2D shadow_pass;
uniform vec2 resolution;
uniform float radius;
void main() {
	const float samples = float( VSM_SAMPLES );
	float mean = 0.0;
	float squared_mean = 0.0;
	float uvStride = samples <= 1.0 ? 0.0 : 2.0 / ( samples - 1.0 );
	float uvStart = samples <= 1.0 ? 0.0 : - 1.0;
	for ( float i = 0.0; i < samples; i ++ ) {
		float uvOffset = uvStart + i * uvStride;
		#ifdef HORIZONTAL_PASS
			vec2 distribution = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( uvOffset, 0.0 ) * radius ) / resolution ).rg;
			mean += distribution.x;
			squared_mean += distribution.y * distribution.y + distribution.x * distribution.x;
		#else
			float depth = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( 0.0, uvOffset ) * radius ) / resolution ).r;
			mean += depth;
			squared_mean += depth * depth;
		#endif
	}
	mean = mean / samples;
	squared_mean = squared_mean / samples;
	float std_dev = sqrt( max( 0.0, squared_mean - mean * mean ) );
	gl_FragColor = vec4( mean, std_dev, 0.0, 1.0 );
}`,cS=[new W(1,0,0),new W(-1,0,0),new W(0,1,0),new W(0,-1,0),new W(0,0,1),new W(0,0,-1)],hS=[new W(0,-1,0),new W(0,-1,0),new W(0,0,1),new W(0,0,-1),new W(0,-1,0),new W(0,-1,0)],tm=new kt,Ca=new W,Yu=new W;function uS(i,e,t){let n=new Os,s=new je,r=new je,o=new Ct,a=new Ol,c=new Bl,l={},d=t.maxTextureSize,u={[Ws]:Yn,[Yn]:Ws,[Zi]:Zi},h=new yi({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new je},radius:{value:4}},vertexShader:aS,fragmentShader:lS}),m=h.clone();m.defines.HORIZONTAL_PASS=1;let g=new An;g.setAttribute("position",new Kn(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));let v=new Pn(g,h),p=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=va;let f=this.type;this.render=function(b,_,A){if(p.enabled===!1||p.autoUpdate===!1&&p.needsUpdate===!1||b.length===0)return;this.type===jf&&(Ye("WebGLShadowMap: PCFSoftShadowMap has been removed. Using PCFShadowMap instead."),this.type=va);let H=i.getRenderTarget(),O=i.getActiveCubeFace(),T=i.getActiveMipmapLevel(),F=i.state;F.setBlending(or),F.buffers.depth.getReversed()===!0?F.buffers.color.setClear(0,0,0,0):F.buffers.color.setClear(1,1,1,1),F.buffers.depth.setTest(!0),F.setScissorTest(!1);let B=f!==this.type;B&&_.traverse(function(D){D.material&&(Array.isArray(D.material)?D.material.forEach(V=>V.needsUpdate=!0):D.material.needsUpdate=!0)});for(let D=0,V=b.length;D<V;D++){let Y=b[D],$=Y.shadow;if($===void 0){Ye("WebGLShadowMap:",Y,"has no shadow.");continue}if($.autoUpdate===!1&&$.needsUpdate===!1)continue;s.copy($.mapSize);let ce=$.getFrameExtents();s.multiply(ce),r.copy($.mapSize),(s.x>d||s.y>d)&&(s.x>d&&(r.x=Math.floor(d/ce.x),s.x=r.x*ce.x,$.mapSize.x=r.x),s.y>d&&(r.y=Math.floor(d/ce.y),s.y=r.y*ce.y,$.mapSize.y=r.y));let P=i.state.buffers.depth.getReversed();if($.camera._reversedDepth=P,$.map===null||B===!0){if($.map!==null&&($.map.depthTexture!==null&&($.map.depthTexture.dispose(),$.map.depthTexture=null),$.map.dispose()),this.type===no){if(Y.isPointLight){Ye("WebGLShadowMap: VSM shadow maps are not supported for PointLights. Use PCF or BasicShadowMap instead.");continue}$.map=new hi(s.x,s.y,{format:$s,type:Ni,minFilter:Xn,magFilter:Xn,generateMipmaps:!1}),$.map.texture.name=Y.name+".shadowMap",$.map.depthTexture=new vs(s.x,s.y,Di),$.map.depthTexture.name=Y.name+".shadowMapDepth",$.map.depthTexture.format=ms,$.map.depthTexture.compareFunction=null,$.map.depthTexture.minFilter=Tn,$.map.depthTexture.magFilter=Tn}else Y.isPointLight?($.map=new Ia(s.x),$.map.depthTexture=new na(s.x,Li)):($.map=new hi(s.x,s.y),$.map.depthTexture=new vs(s.x,s.y,Li)),$.map.depthTexture.name=Y.name+".shadowMap",$.map.depthTexture.format=ms,this.type===va?($.map.depthTexture.compareFunction=P?Pu:Cu,$.map.depthTexture.minFilter=Xn,$.map.depthTexture.magFilter=Xn):($.map.depthTexture.compareFunction=null,$.map.depthTexture.minFilter=Tn,$.map.depthTexture.magFilter=Tn);$.camera.updateProjectionMatrix()}$.map.isWebGLCubeRenderTarget!==!0&&($.map.width!==s.x||$.map.height!==s.y)&&$.map.setSize(s.x,s.y);let I=$.map.isWebGLCubeRenderTarget?6:$.getViewportCount();Y.isPointLight!==!0&&$.updateMatrices(Y,A);let q=($.camera.layers.mask&4294967294)!==0?$.camera.layers:A.layers;for(let ie=0;ie<I;ie++){let he=$.getCamera(ie);if(Y.isPointLight){let Q=$.camera,fe=$.matrix,le=Y.distance||Q.far;le!==Q.far&&(Q.far=le,Q.updateProjectionMatrix()),Ca.setFromMatrixPosition(Y.matrixWorld),Q.position.copy(Ca),Yu.copy(Q.position),Yu.add(cS[ie]),Q.up.copy(hS[ie]),Q.lookAt(Yu),Q.updateMatrixWorld(),fe.makeTranslation(-Ca.x,-Ca.y,-Ca.z),tm.multiplyMatrices(Q.projectionMatrix,Q.matrixWorldInverse),$._frustum.setFromProjectionMatrix(tm,Q.coordinateSystem,Q.reversedDepth)}if($.map.isWebGLCubeRenderTarget)i.setRenderTarget($.map,ie),i.clear();else{ie===0&&(i.setRenderTarget($.map),i.clear());let Q=$.getViewport(ie);o.set(r.x*Q.x,r.y*Q.y,r.x*Q.z,r.y*Q.w),F.viewport(o)}n=$.getFrustum(ie),M(_,A,he,Y,q,this.type)}$.isPointLightShadow!==!0&&this.type===no&&y($,A),$.needsUpdate=!1}f=this.type,p.needsUpdate=!1,i.setRenderTarget(H,O,T)};function y(b,_){let A=e.update(v);h.defines.VSM_SAMPLES!==b.blurSamples&&(h.defines.VSM_SAMPLES=b.blurSamples,m.defines.VSM_SAMPLES=b.blurSamples,h.needsUpdate=!0,m.needsUpdate=!0),b.mapPass===null?b.mapPass=new hi(s.x,s.y,{format:$s,type:Ni}):(b.mapPass.width!==b.map.width||b.mapPass.height!==b.map.height)&&b.mapPass.setSize(b.map.width,b.map.height),h.uniforms.shadow_pass.value=b.map.depthTexture,h.uniforms.resolution.value.set(b.map.width,b.map.height),h.uniforms.radius.value=b.radius,i.setRenderTarget(b.mapPass),i.clear(),i.renderBufferDirect(_,null,A,h,v,null),m.uniforms.shadow_pass.value=b.mapPass.texture,m.uniforms.resolution.value.set(b.map.width,b.map.height),m.uniforms.radius.value=b.radius,i.setRenderTarget(b.map),i.clear(),i.renderBufferDirect(_,null,A,m,v,null)}function C(b,_,A,H){let O=null,T=A.isPointLight===!0?b.customDistanceMaterial:b.customDepthMaterial;if(T!==void 0)O=T;else if(O=A.isPointLight===!0?c:a,i.localClippingEnabled&&_.clipShadows===!0&&Array.isArray(_.clippingPlanes)&&_.clippingPlanes.length!==0||_.displacementMap&&_.displacementScale!==0||_.alphaMap&&_.alphaTest>0||_.map&&_.alphaTest>0||_.alphaToCoverage===!0){let F=O.uuid,B=_.uuid,D=l[F];D===void 0&&(D={},l[F]=D);let V=D[B];V===void 0&&(V=O.clone(),D[B]=V,_.addEventListener("dispose",R)),O=V}if(O.visible=_.visible,O.wireframe=_.wireframe,H===no?O.side=_.shadowSide!==null?_.shadowSide:_.side:O.side=_.shadowSide!==null?_.shadowSide:u[_.side],O.alphaMap=_.alphaMap,O.alphaTest=_.alphaToCoverage===!0?.5:_.alphaTest,O.map=_.map,O.clipShadows=_.clipShadows,O.clippingPlanes=_.clippingPlanes,O.clipIntersection=_.clipIntersection,O.displacementMap=_.displacementMap,O.displacementScale=_.displacementScale,O.displacementBias=_.displacementBias,O.wireframeLinewidth=_.wireframeLinewidth,O.linewidth=_.linewidth,A.isPointLight===!0&&O.isMeshDistanceMaterial===!0){let F=i.properties.get(O);F.light=A}return O}function M(b,_,A,H,O,T){if(b.visible===!1)return;if(b.layers.test(O)&&(b.isMesh||b.isLine||b.isPoints)&&(b.castShadow||b.receiveShadow&&T===no)&&(!b.frustumCulled||b.intersectsFrustum(n))){b.modelViewMatrix.multiplyMatrices(A.matrixWorldInverse,b.matrixWorld);let D=e.update(b),V=b.material;if(Array.isArray(V)){let Y=D.groups;for(let $=0,ce=Y.length;$<ce;$++){let P=Y[$],I=V[P.materialIndex];if(I&&I.visible){let q=C(b,I,H,T);b.onBeforeShadow(i,b,_,A,D,q,P),i.renderBufferDirect(A,null,D,q,b,P),b.onAfterShadow(i,b,_,A,D,q,P)}}}else if(V.visible){let Y=C(b,V,H,T);b.onBeforeShadow(i,b,_,A,D,Y,null),i.renderBufferDirect(A,null,D,Y,b,null),b.onAfterShadow(i,b,_,A,D,Y,null)}}let B=b.children;for(let D=0,V=B.length;D<V;D++)M(B[D],_,A,H,O,T)}function R(b){b.target.removeEventListener("dispose",R);for(let A in l){let H=l[A],O=b.target.uuid;O in H&&(H[O].dispose(),delete H[O])}}}function dS(i,e){function t(){let k=!1,re=new Ct,ne=null,we=new Ct(0,0,0,0);return{setMask:function(xe){ne!==xe&&!k&&(i.colorMask(xe,xe,xe,xe),ne=xe)},setLocked:function(xe){k=xe},setClear:function(xe,Se,Ge,et,ue){ue===!0&&(xe*=et,Se*=et,Ge*=et),re.set(xe,Se,Ge,et),we.equals(re)===!1&&(i.clearColor(xe,Se,Ge,et),we.copy(re))},reset:function(){k=!1,ne=null,we.set(-1,0,0,0)}}}function n(){let k=!1,re=!1,ne=null,we=null,xe=null;return{setReversed:function(Se){if(re!==Se){let Ge=e.get("EXT_clip_control");Se?Ge.clipControlEXT(Ge.LOWER_LEFT_EXT,Ge.ZERO_TO_ONE_EXT):Ge.clipControlEXT(Ge.LOWER_LEFT_EXT,Ge.NEGATIVE_ONE_TO_ONE_EXT),re=Se;let et=xe;xe=null,this.setClear(et)}},getReversed:function(){return re},setTest:function(Se){Se?pe(i.DEPTH_TEST):De(i.DEPTH_TEST)},setMask:function(Se){ne!==Se&&!k&&(i.depthMask(Se),ne=Se)},setFunc:function(Se){if(re&&(Se=Ip[Se]),we!==Se){switch(Se){case xl:i.depthFunc(i.NEVER);break;case vl:i.depthFunc(i.ALWAYS);break;case yl:i.depthFunc(i.LESS);break;case Xr:i.depthFunc(i.LEQUAL);break;case bl:i.depthFunc(i.EQUAL);break;case Sl:i.depthFunc(i.GEQUAL);break;case Ml:i.depthFunc(i.GREATER);break;case wl:i.depthFunc(i.NOTEQUAL);break;default:i.depthFunc(i.LEQUAL)}we=Se}},setLocked:function(Se){k=Se},setClear:function(Se){xe!==Se&&(xe=Se,re&&(Se=1-Se),i.clearDepth(Se))},reset:function(){k=!1,ne=null,we=null,xe=null,re=!1}}}function s(){let k=!1,re=null,ne=null,we=null,xe=null,Se=null,Ge=null,et=null,ue=null;return{setTest:function(ke){k||(ke?pe(i.STENCIL_TEST):De(i.STENCIL_TEST))},setMask:function(ke){re!==ke&&!k&&(i.stencilMask(ke),re=ke)},setFunc:function(ke,tt,Ae){(ne!==ke||we!==tt||xe!==Ae)&&(i.stencilFunc(ke,tt,Ae),ne=ke,we=tt,xe=Ae)},setOp:function(ke,tt,Ae){(Se!==ke||Ge!==tt||et!==Ae)&&(i.stencilOp(ke,tt,Ae),Se=ke,Ge=tt,et=Ae)},setLocked:function(ke){k=ke},setClear:function(ke){ue!==ke&&(i.clearStencil(ke),ue=ke)},reset:function(){k=!1,re=null,ne=null,we=null,xe=null,Se=null,Ge=null,et=null,ue=null}}}let r=new t,o=new n,a=new s,c={},l=new WeakMap,d={},u={},h={},m=new WeakMap,g=[],v=null,p=!1,f=null,y=null,C=null,M=null,R=null,b=null,_=null,A=new ct(0,0,0),H=0,O=!1,T=null,F=null,B=null,D=null,V=null,Y=i.getParameter(i.MAX_COMBINED_TEXTURE_IMAGE_UNITS),$=!1,ce=0,P=i.getParameter(i.VERSION);P.indexOf("WebGL")!==-1?(ce=parseFloat(/^WebGL (\d)/.exec(P)[1]),$=ce>=1):P.indexOf("OpenGL ES")!==-1&&(ce=parseFloat(/^OpenGL ES (\d)/.exec(P)[1]),$=ce>=2);let I=null,q={},ie=i.getParameter(i.SCISSOR_BOX),he=i.getParameter(i.VIEWPORT),Q=new Ct().fromArray(ie),fe=new Ct().fromArray(he);function le(k,re,ne,we){let xe=new Uint8Array(4),Se=i.createTexture();i.bindTexture(k,Se),i.texParameteri(k,i.TEXTURE_MIN_FILTER,i.NEAREST),i.texParameteri(k,i.TEXTURE_MAG_FILTER,i.NEAREST);for(let Ge=0;Ge<ne;Ge++)k===i.TEXTURE_3D||k===i.TEXTURE_2D_ARRAY?i.texImage3D(re,0,i.RGBA,1,1,we,0,i.RGBA,i.UNSIGNED_BYTE,xe):i.texImage2D(re+Ge,0,i.RGBA,1,1,0,i.RGBA,i.UNSIGNED_BYTE,xe);return Se}let me={};me[i.TEXTURE_2D]=le(i.TEXTURE_2D,i.TEXTURE_2D,1),me[i.TEXTURE_CUBE_MAP]=le(i.TEXTURE_CUBE_MAP,i.TEXTURE_CUBE_MAP_POSITIVE_X,6),me[i.TEXTURE_2D_ARRAY]=le(i.TEXTURE_2D_ARRAY,i.TEXTURE_2D_ARRAY,1,1),me[i.TEXTURE_3D]=le(i.TEXTURE_3D,i.TEXTURE_3D,1,1),r.setClear(0,0,0,1),o.setClear(1),a.setClear(0),pe(i.DEPTH_TEST),o.setFunc(Xr),sn(!1),Nt(au),pe(i.CULL_FACE),bt(or);function pe(k){d[k]!==!0&&(i.enable(k),d[k]=!0)}function De(k){d[k]!==!1&&(i.disable(k),d[k]=!1)}function Ze(k,re){return h[k]!==re?(i.bindFramebuffer(k,re),h[k]=re,k===i.DRAW_FRAMEBUFFER&&(h[i.FRAMEBUFFER]=re),k===i.FRAMEBUFFER&&(h[i.DRAW_FRAMEBUFFER]=re),!0):!1}function Ne(k,re){let ne=g,we=!1;if(k){ne=m.get(re),ne===void 0&&(ne=[],m.set(re,ne));let xe=k.textures;if(ne.length!==xe.length||ne[0]!==i.COLOR_ATTACHMENT0){for(let Se=0,Ge=xe.length;Se<Ge;Se++)ne[Se]=i.COLOR_ATTACHMENT0+Se;ne.length=xe.length,we=!0}}else ne[0]!==i.BACK&&(ne[0]=i.BACK,we=!0);we&&i.drawBuffers(ne)}function qe(k){return v!==k?(i.useProgram(k),v=k,!0):!1}let ot={[ar]:i.FUNC_ADD,[ep]:i.FUNC_SUBTRACT,[tp]:i.FUNC_REVERSE_SUBTRACT};ot[np]=i.MIN,ot[ip]=i.MAX;let Qe={[sp]:i.ZERO,[rp]:i.ONE,[op]:i.SRC_COLOR,[uu]:i.SRC_ALPHA,[dp]:i.SRC_ALPHA_SATURATE,[hp]:i.DST_COLOR,[lp]:i.DST_ALPHA,[ap]:i.ONE_MINUS_SRC_COLOR,[du]:i.ONE_MINUS_SRC_ALPHA,[up]:i.ONE_MINUS_DST_COLOR,[cp]:i.ONE_MINUS_DST_ALPHA,[fp]:i.CONSTANT_COLOR,[pp]:i.ONE_MINUS_CONSTANT_COLOR,[mp]:i.CONSTANT_ALPHA,[gp]:i.ONE_MINUS_CONSTANT_ALPHA};function bt(k,re,ne,we,xe,Se,Ge,et,ue,ke){if(k===or){p===!0&&(De(i.BLEND),p=!1);return}if(p===!1&&(pe(i.BLEND),p=!0),k!==Qf){if(k!==f||ke!==O){if((y!==ar||R!==ar)&&(i.blendEquation(i.FUNC_ADD),y=ar,R=ar),ke)switch(k){case io:i.blendFuncSeparate(i.ONE,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case lu:i.blendFunc(i.ONE,i.ONE);break;case cu:i.blendFuncSeparate(i.ZERO,i.ONE_MINUS_SRC_COLOR,i.ZERO,i.ONE);break;case hu:i.blendFuncSeparate(i.DST_COLOR,i.ONE_MINUS_SRC_ALPHA,i.ZERO,i.ONE);break;default:it("WebGLState: Invalid blending: ",k);break}else switch(k){case io:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE_MINUS_SRC_ALPHA,i.ONE,i.ONE_MINUS_SRC_ALPHA);break;case lu:i.blendFuncSeparate(i.SRC_ALPHA,i.ONE,i.ONE,i.ONE);break;case cu:it("WebGLState: SubtractiveBlending requires material.premultipliedAlpha = true");break;case hu:it("WebGLState: MultiplyBlending requires material.premultipliedAlpha = true");break;default:it("WebGLState: Invalid blending: ",k);break}C=null,M=null,b=null,_=null,A.set(0,0,0),H=0,f=k,O=ke}return}xe=xe||re,Se=Se||ne,Ge=Ge||we,(re!==y||xe!==R)&&(i.blendEquationSeparate(ot[re],ot[xe]),y=re,R=xe),(ne!==C||we!==M||Se!==b||Ge!==_)&&(i.blendFuncSeparate(Qe[ne],Qe[we],Qe[Se],Qe[Ge]),C=ne,M=we,b=Se,_=Ge),(et.equals(A)===!1||ue!==H)&&(i.blendColor(et.r,et.g,et.b,ue),A.copy(et),H=ue),f=k,O=!1}function At(k,re){k.side===Zi?De(i.CULL_FACE):pe(i.CULL_FACE);let ne=k.side===Yn;re&&(ne=!ne),sn(ne),k.blending===io&&k.transparent===!1?bt(or):bt(k.blending,k.blendEquation,k.blendSrc,k.blendDst,k.blendEquationAlpha,k.blendSrcAlpha,k.blendDstAlpha,k.blendColor,k.blendAlpha,k.premultipliedAlpha),o.setFunc(k.depthFunc),o.setTest(k.depthTest),o.setMask(k.depthWrite),r.setMask(k.colorWrite);let we=k.stencilWrite;a.setTest(we),we&&(a.setMask(k.stencilWriteMask),a.setFunc(k.stencilFunc,k.stencilRef,k.stencilFuncMask),a.setOp(k.stencilFail,k.stencilZFail,k.stencilZPass)),yt(k.polygonOffset,k.polygonOffsetFactor,k.polygonOffsetUnits),k.alphaToCoverage===!0?pe(i.SAMPLE_ALPHA_TO_COVERAGE):De(i.SAMPLE_ALPHA_TO_COVERAGE)}function sn(k){T!==k&&(k?i.frontFace(i.CW):i.frontFace(i.CCW),T=k)}function Nt(k){k!==Jf?(pe(i.CULL_FACE),k!==F&&(k===au?i.cullFace(i.BACK):k===Kf?i.cullFace(i.FRONT):i.cullFace(i.FRONT_AND_BACK))):De(i.CULL_FACE),F=k}function yn(k){k!==B&&($&&i.lineWidth(k),B=k)}function yt(k,re,ne){k?(pe(i.POLYGON_OFFSET_FILL),(D!==re||V!==ne)&&(D=re,V=ne,o.getReversed()&&(re=-re,ne=-ne),i.polygonOffset(re,ne))):De(i.POLYGON_OFFSET_FILL)}function fn(k){k?pe(i.SCISSOR_TEST):De(i.SCISSOR_TEST)}function Jt(k){k===void 0&&(k=i.TEXTURE0+Y-1),I!==k&&(i.activeTexture(k),I=k)}function rn(k,re,ne){ne===void 0&&(I===null?ne=i.TEXTURE0+Y-1:ne=I);let we=q[ne];we===void 0&&(we={type:void 0,texture:void 0},q[ne]=we),(we.type!==k||we.texture!==re)&&(I!==ne&&(i.activeTexture(ne),I=ne),i.bindTexture(k,re||me[k]),we.type=k,we.texture=re)}function z(){let k=q[I];k!==void 0&&k.type!==void 0&&(i.bindTexture(k.type,null),k.type=void 0,k.texture=void 0)}function Re(){try{i.compressedTexImage2D(...arguments)}catch(k){it("WebGLState:",k)}}function Je(){try{i.compressedTexImage3D(...arguments)}catch(k){it("WebGLState:",k)}}function at(){try{i.texSubImage2D(...arguments)}catch(k){it("WebGLState:",k)}}function Me(){try{i.texSubImage3D(...arguments)}catch(k){it("WebGLState:",k)}}function Bt(){try{i.compressedTexSubImage2D(...arguments)}catch(k){it("WebGLState:",k)}}function He(){try{i.compressedTexSubImage3D(...arguments)}catch(k){it("WebGLState:",k)}}function $e(){try{i.texStorage2D(...arguments)}catch(k){it("WebGLState:",k)}}function L(){try{i.texStorage3D(...arguments)}catch(k){it("WebGLState:",k)}}function S(){try{i.texImage2D(...arguments)}catch(k){it("WebGLState:",k)}}function Z(){try{i.texImage3D(...arguments)}catch(k){it("WebGLState:",k)}}function de(k){return u[k]!==void 0?u[k]:i.getParameter(k)}function oe(k,re){u[k]!==re&&(i.pixelStorei(k,re),u[k]=re)}function ve(k){Q.equals(k)===!1&&(i.scissor(k.x,k.y,k.z,k.w),Q.copy(k))}function ye(k){fe.equals(k)===!1&&(i.viewport(k.x,k.y,k.z,k.w),fe.copy(k))}function te(k,re){let ne=l.get(re);ne===void 0&&(ne=new WeakMap,l.set(re,ne));let we=ne.get(k);we===void 0&&(we=i.getUniformBlockIndex(re,k.name),i.uniformBlockBinding(re,we,we),ne.set(k,we))}function se(k,re,ne){let xe=l.get(re).get(k);c[xe]!==ne&&(i.bindBufferBase(i.UNIFORM_BUFFER,xe,ne),c[xe]=ne)}function _e(){i.disable(i.BLEND),i.disable(i.CULL_FACE),i.disable(i.DEPTH_TEST),i.disable(i.POLYGON_OFFSET_FILL),i.disable(i.SCISSOR_TEST),i.disable(i.STENCIL_TEST),i.disable(i.SAMPLE_ALPHA_TO_COVERAGE),i.blendEquation(i.FUNC_ADD),i.blendFunc(i.ONE,i.ZERO),i.blendFuncSeparate(i.ONE,i.ZERO,i.ONE,i.ZERO),i.blendColor(0,0,0,0),i.colorMask(!0,!0,!0,!0),i.clearColor(0,0,0,0),i.depthMask(!0),i.depthFunc(i.LESS),o.setReversed(!1),i.clearDepth(1),i.stencilMask(4294967295),i.stencilFunc(i.ALWAYS,0,4294967295),i.stencilOp(i.KEEP,i.KEEP,i.KEEP),i.clearStencil(0),i.cullFace(i.BACK),i.frontFace(i.CCW),i.polygonOffset(0,0),i.activeTexture(i.TEXTURE0),i.bindFramebuffer(i.FRAMEBUFFER,null),i.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),i.bindFramebuffer(i.READ_FRAMEBUFFER,null),i.useProgram(null),i.lineWidth(1),i.scissor(0,0,i.canvas.width,i.canvas.height),i.viewport(0,0,i.canvas.width,i.canvas.height),i.pixelStorei(i.PACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_ALIGNMENT,4),i.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,!1),i.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,!1),i.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,i.BROWSER_DEFAULT_WEBGL),i.pixelStorei(i.PACK_ROW_LENGTH,0),i.pixelStorei(i.PACK_SKIP_PIXELS,0),i.pixelStorei(i.PACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_ROW_LENGTH,0),i.pixelStorei(i.UNPACK_IMAGE_HEIGHT,0),i.pixelStorei(i.UNPACK_SKIP_PIXELS,0),i.pixelStorei(i.UNPACK_SKIP_ROWS,0),i.pixelStorei(i.UNPACK_SKIP_IMAGES,0),d={},u={},I=null,q={},h={},c={},m=new WeakMap,g=[],v=null,p=!1,f=null,y=null,C=null,M=null,R=null,b=null,_=null,A=new ct(0,0,0),H=0,O=!1,T=null,F=null,B=null,D=null,V=null,Q.set(0,0,i.canvas.width,i.canvas.height),fe.set(0,0,i.canvas.width,i.canvas.height),r.reset(),o.reset(),a.reset()}return{buffers:{color:r,depth:o,stencil:a},enable:pe,disable:De,bindFramebuffer:Ze,drawBuffers:Ne,useProgram:qe,setBlending:bt,setMaterial:At,setFlipSided:sn,setCullFace:Nt,setLineWidth:yn,setPolygonOffset:yt,setScissorTest:fn,activeTexture:Jt,bindTexture:rn,unbindTexture:z,compressedTexImage2D:Re,compressedTexImage3D:Je,texImage2D:S,texImage3D:Z,pixelStorei:oe,getParameter:de,updateUBOMapping:te,uniformBlockBinding:se,texStorage2D:$e,texStorage3D:L,texSubImage2D:at,texSubImage3D:Me,compressedTexSubImage2D:Bt,compressedTexSubImage3D:He,scissor:ve,viewport:ye,reset:_e}}function fS(i,e,t,n,s,r,o){let a=e.has("WEBGL_multisampled_render_to_texture")?e.get("WEBGL_multisampled_render_to_texture"):null,c=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),l=new je,d=new WeakMap,u=new Set,h,m=new WeakMap,g=new Set,v=new FinalizationRegistry(L=>g.delete(L)),p=!1;try{p=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function f(L,S){return p?new OffscreenCanvas(L,S):qo("canvas")}function y(L,S,Z){let de=1,oe=$e(L);if((oe.width>Z||oe.height>Z)&&(de=Z/Math.max(oe.width,oe.height)),de<1)if(typeof HTMLImageElement<"u"&&L instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&L instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&L instanceof ImageBitmap||typeof VideoFrame<"u"&&L instanceof VideoFrame){let ve=Math.floor(de*oe.width),ye=Math.floor(de*oe.height);h===void 0&&(h=f(ve,ye));let te=S?f(ve,ye):h;return te.width=ve,te.height=ye,te.getContext("2d").drawImage(L,0,0,ve,ye),Ye("WebGLRenderer: Texture has been resized from ("+oe.width+"x"+oe.height+") to ("+ve+"x"+ye+")."),te}else return"data"in L&&Ye("WebGLRenderer: Image in DataTexture is too big ("+oe.width+"x"+oe.height+")."),L;return L}function C(L){return L.generateMipmaps}function M(L){i.generateMipmap(L)}function R(L){return L.isWebGLCubeRenderTarget?i.TEXTURE_CUBE_MAP:L.isWebGL3DRenderTarget?i.TEXTURE_3D:L.isWebGLArrayRenderTarget||L.isCompressedArrayTexture?i.TEXTURE_2D_ARRAY:i.TEXTURE_2D}function b(L,S,Z,de,oe,ve=!1){if(L!==null){if(i[L]!==void 0)return i[L];Ye("WebGLRenderer: Attempt to use non-existing WebGL internal format '"+L+"'")}let ye;de&&(ye=e.get("EXT_texture_norm16"),ye||Ye("WebGLRenderer: Unable to use normalized textures without EXT_texture_norm16 extension"));let te=S;if(S===i.RED&&(Z===i.FLOAT&&(te=i.R32F),Z===i.HALF_FLOAT&&(te=i.R16F),Z===i.UNSIGNED_BYTE&&(te=i.R8),Z===i.UNSIGNED_SHORT&&ye&&(te=ye.R16_EXT),Z===i.SHORT&&ye&&(te=ye.R16_SNORM_EXT)),S===i.RED_INTEGER&&(Z===i.UNSIGNED_BYTE&&(te=i.R8UI),Z===i.UNSIGNED_SHORT&&(te=i.R16UI),Z===i.UNSIGNED_INT&&(te=i.R32UI),Z===i.BYTE&&(te=i.R8I),Z===i.SHORT&&(te=i.R16I),Z===i.INT&&(te=i.R32I)),S===i.RG&&(Z===i.FLOAT&&(te=i.RG32F),Z===i.HALF_FLOAT&&(te=i.RG16F),Z===i.UNSIGNED_BYTE&&(te=i.RG8),Z===i.UNSIGNED_SHORT&&ye&&(te=ye.RG16_EXT),Z===i.SHORT&&ye&&(te=ye.RG16_SNORM_EXT)),S===i.RG_INTEGER&&(Z===i.UNSIGNED_BYTE&&(te=i.RG8UI),Z===i.UNSIGNED_SHORT&&(te=i.RG16UI),Z===i.UNSIGNED_INT&&(te=i.RG32UI),Z===i.BYTE&&(te=i.RG8I),Z===i.SHORT&&(te=i.RG16I),Z===i.INT&&(te=i.RG32I)),S===i.RGB_INTEGER&&(Z===i.UNSIGNED_BYTE&&(te=i.RGB8UI),Z===i.UNSIGNED_SHORT&&(te=i.RGB16UI),Z===i.UNSIGNED_INT&&(te=i.RGB32UI),Z===i.BYTE&&(te=i.RGB8I),Z===i.SHORT&&(te=i.RGB16I),Z===i.INT&&(te=i.RGB32I)),S===i.RGBA_INTEGER&&(Z===i.UNSIGNED_BYTE&&(te=i.RGBA8UI),Z===i.UNSIGNED_SHORT&&(te=i.RGBA16UI),Z===i.UNSIGNED_INT&&(te=i.RGBA32UI),Z===i.BYTE&&(te=i.RGBA8I),Z===i.SHORT&&(te=i.RGBA16I),Z===i.INT&&(te=i.RGBA32I)),S===i.RGB&&(Z===i.UNSIGNED_SHORT&&ye&&(te=ye.RGB16_EXT),Z===i.SHORT&&ye&&(te=ye.RGB16_SNORM_EXT),Z===i.UNSIGNED_INT_5_9_9_9_REV&&(te=i.RGB9_E5),Z===i.UNSIGNED_INT_10F_11F_11F_REV&&(te=i.R11F_G11F_B10F)),S===i.RGBA){let se=ve?Xo:_t.getTransfer(oe);Z===i.FLOAT&&(te=i.RGBA32F),Z===i.HALF_FLOAT&&(te=i.RGBA16F),Z===i.UNSIGNED_BYTE&&(te=se===Rt?i.SRGB8_ALPHA8:i.RGBA8),Z===i.UNSIGNED_SHORT&&ye&&(te=ye.RGBA16_EXT),Z===i.SHORT&&ye&&(te=ye.RGBA16_SNORM_EXT),Z===i.UNSIGNED_SHORT_4_4_4_4&&(te=i.RGBA4),Z===i.UNSIGNED_SHORT_5_5_5_1&&(te=i.RGB5_A1)}return(te===i.R16F||te===i.R32F||te===i.RG16F||te===i.RG32F||te===i.RGBA16F||te===i.RGBA32F)&&e.get("EXT_color_buffer_float"),te}function _(L,S){let Z;return L?S===null||S===Li||S===cr?Z=i.DEPTH24_STENCIL8:S===Di?Z=i.DEPTH32F_STENCIL8:S===ro&&(Z=i.DEPTH24_STENCIL8,Ye("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):S===null||S===Li||S===cr?Z=i.DEPTH_COMPONENT24:S===Di?Z=i.DEPTH_COMPONENT32F:S===ro&&(Z=i.DEPTH_COMPONENT16),Z}function A(L,S){return C(L)===!0||L.isFramebufferTexture&&L.minFilter!==Tn&&L.minFilter!==Xn?Math.log2(Math.max(S.width,S.height))+1:L.mipmaps.length>0?L.mipmaps.length:L.isCompressedTexture&&Array.isArray(L.image)?S.mipmaps.length:1}function H(L){let S=new WeakRef(L);n.get(L).__ref=S,g.add(S),v.register(L,S,S)}function O(L){let S=n.get(L).__ref;S!==void 0&&(g.delete(S),v.unregister(S))}function T(L){B(L.target)}function F(L){D(L.target)}function B(L){L.removeEventListener("dispose",T),O(L),Y(L),L.isVideoTexture&&d.delete(L),L.isHTMLTexture&&u.delete(L)}function D(L){L.removeEventListener("dispose",F),O(L),ce(L)}function V(){for(let L of g){let S=L.deref();S!==void 0&&(S.isRenderTarget===!0?D(S):B(S))}g.clear(),u.clear()}function Y(L){let S=n.get(L);if(S.__webglInit===void 0)return;let Z=L.source,de=m.get(Z);if(de){let oe=de[S.__cacheKey];oe.usedTimes--,oe.usedTimes===0&&$(L),Object.keys(de).length===0&&m.delete(Z)}n.remove(L)}function $(L){let S=n.get(L);i.deleteTexture(S.__webglTexture);let Z=L.source,de=m.get(Z);delete de[S.__cacheKey],o.memory.textures--}function ce(L){let S=n.get(L);S.__depthDisposeCallback&&S.__depthDisposeCallback();let Z=L.depthTexture;if(Z&&Z.renderTarget===L&&B(Z),L.isWebGLCubeRenderTarget)for(let oe=0;oe<6;oe++){if(Array.isArray(S.__webglFramebuffer[oe]))for(let ve=0;ve<S.__webglFramebuffer[oe].length;ve++)i.deleteFramebuffer(S.__webglFramebuffer[oe][ve]);else i.deleteFramebuffer(S.__webglFramebuffer[oe]);S.__webglDepthbuffer&&i.deleteRenderbuffer(S.__webglDepthbuffer[oe])}else{if(Array.isArray(S.__webglFramebuffer))for(let oe=0;oe<S.__webglFramebuffer.length;oe++)i.deleteFramebuffer(S.__webglFramebuffer[oe]);else i.deleteFramebuffer(S.__webglFramebuffer);if(S.__webglDepthbuffer&&i.deleteRenderbuffer(S.__webglDepthbuffer),S.__webglMultisampledFramebuffer&&i.deleteFramebuffer(S.__webglMultisampledFramebuffer),S.__webglColorRenderbuffer)for(let oe=0;oe<S.__webglColorRenderbuffer.length;oe++)S.__webglColorRenderbuffer[oe]&&i.deleteRenderbuffer(S.__webglColorRenderbuffer[oe]);S.__webglDepthRenderbuffer&&i.deleteRenderbuffer(S.__webglDepthRenderbuffer)}let de=L.textures;for(let oe=0,ve=de.length;oe<ve;oe++){let ye=n.get(de[oe]);ye.__webglTexture&&(i.deleteTexture(ye.__webglTexture),o.memory.textures--),n.remove(de[oe])}n.remove(L)}let P=0;function I(){P=0}function q(){return P}function ie(L){P=L}function he(){let L=P;return L>=s.maxTextures&&Ye("WebGLTextures: Trying to use "+(L+1)+" texture units while this GPU supports only "+s.maxTextures),P+=1,L}function Q(L){let S=[];return S.push(L.wrapS),S.push(L.wrapT),S.push(L.wrapR||0),S.push(L.magFilter),S.push(L.minFilter),S.push(L.anisotropy),S.push(L.internalFormat),S.push(L.format),S.push(L.type),S.push(L.generateMipmaps),S.push(L.mipmapsAutoUpdate),S.push(L.premultiplyAlpha),S.push(L.flipY),S.push(L.unpackAlignment),S.push(L.colorSpace),S.join()}function fe(L,S){let Z=n.get(L);if(L.isVideoTexture&&Bt(L),L.isRenderTargetTexture===!1&&L.isExternalTexture!==!0&&L.version>0&&Z.__version!==L.version){let de=L.image;if(de===null)Ye("WebGLRenderer: Texture marked for update but no image data found.");else if(de.complete===!1)Ye("WebGLRenderer: Texture marked for update but image is incomplete");else{At(Z,L,S);return}}else L.isExternalTexture&&(Z.__webglTexture=L.sourceTexture?L.sourceTexture:null);t.bindTexture(i.TEXTURE_2D,Z.__webglTexture,i.TEXTURE0+S)}function le(L,S){let Z=n.get(L);if(L.isRenderTargetTexture===!1&&L.version>0&&Z.__version!==L.version){At(Z,L,S);return}else L.isExternalTexture&&(Z.__webglTexture=L.sourceTexture?L.sourceTexture:null);t.bindTexture(i.TEXTURE_2D_ARRAY,Z.__webglTexture,i.TEXTURE0+S)}function me(L,S){let Z=n.get(L);if(L.isRenderTargetTexture===!1&&L.version>0&&Z.__version!==L.version){At(Z,L,S);return}t.bindTexture(i.TEXTURE_3D,Z.__webglTexture,i.TEXTURE0+S)}function pe(L,S){let Z=n.get(L);if(L.version>0&&Z.__version!==L.version){sn(Z,L,S);return}t.bindTexture(i.TEXTURE_CUBE_MAP,Z.__webglTexture,i.TEXTURE0+S)}let De={[El]:i.REPEAT,[qi]:i.CLAMP_TO_EDGE,[Tl]:i.MIRRORED_REPEAT},Ze={[Tn]:i.NEAREST,[vp]:i.NEAREST_MIPMAP_NEAREST,[ya]:i.NEAREST_MIPMAP_LINEAR,[Xn]:i.LINEAR,[ec]:i.LINEAR_MIPMAP_NEAREST,[ys]:i.LINEAR_MIPMAP_LINEAR},Ne={[Mp]:i.NEVER,[Iu]:i.ALWAYS,[wp]:i.LESS,[Cu]:i.LEQUAL,[Ep]:i.EQUAL,[Pu]:i.GEQUAL,[Tp]:i.GREATER,[Ap]:i.NOTEQUAL};function qe(L,S){if(S.type===Di&&e.has("OES_texture_float_linear")===!1&&(S.magFilter===Xn||S.magFilter===ec||S.magFilter===ya||S.magFilter===ys||S.minFilter===Xn||S.minFilter===ec||S.minFilter===ya||S.minFilter===ys)&&Ye("WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),i.texParameteri(L,i.TEXTURE_WRAP_S,De[S.wrapS]),i.texParameteri(L,i.TEXTURE_WRAP_T,De[S.wrapT]),(L===i.TEXTURE_3D||L===i.TEXTURE_2D_ARRAY)&&i.texParameteri(L,i.TEXTURE_WRAP_R,De[S.wrapR]),i.texParameteri(L,i.TEXTURE_MAG_FILTER,Ze[S.magFilter]),i.texParameteri(L,i.TEXTURE_MIN_FILTER,Ze[S.minFilter]),S.compareFunction&&(i.texParameteri(L,i.TEXTURE_COMPARE_MODE,i.COMPARE_REF_TO_TEXTURE),i.texParameteri(L,i.TEXTURE_COMPARE_FUNC,Ne[S.compareFunction])),e.has("EXT_texture_filter_anisotropic")===!0){if(S.magFilter===Tn||S.minFilter!==ya&&S.minFilter!==ys||S.type===Di&&e.has("OES_texture_float_linear")===!1)return;if(S.anisotropy>1||n.get(S).__currentAnisotropy){let Z=e.get("EXT_texture_filter_anisotropic");i.texParameterf(L,Z.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(S.anisotropy,s.getMaxAnisotropy())),n.get(S).__currentAnisotropy=S.anisotropy}}}function ot(L,S){let Z=!1;L.__webglInit===void 0&&(L.__webglInit=!0,S.addEventListener("dispose",T),H(S));let de=S.source,oe=m.get(de);oe===void 0&&(oe={},m.set(de,oe));let ve=Q(S);if(ve!==L.__cacheKey){oe[ve]===void 0&&(oe[ve]={texture:i.createTexture(),usedTimes:0},o.memory.textures++,Z=!0),oe[ve].usedTimes++;let ye=oe[L.__cacheKey];ye!==void 0&&(oe[L.__cacheKey].usedTimes--,ye.usedTimes===0&&$(S)),L.__cacheKey=ve,L.__webglTexture=oe[ve].texture}return Z}function Qe(L,S,Z){return Math.floor(Math.floor(L/Z)/S)}function bt(L,S,Z,de){let ve=L.updateRanges;if(ve.length===0)t.texSubImage2D(i.TEXTURE_2D,0,0,0,S.width,S.height,Z,de,S.data);else{ve.sort((k,re)=>k.start-re.start);let ye=0;for(let k=1;k<ve.length;k++){let re=ve[ye],ne=ve[k],we=re.start+re.count,xe=Qe(ne.start,S.width,4),Se=Qe(re.start,S.width,4);ne.start<=we+1&&xe===Se&&Qe(ne.start+ne.count-1,S.width,4)===xe?re.count=Math.max(re.count,ne.start+ne.count-re.start):(++ye,ve[ye]=ne)}ve.length=ye+1;let te=t.getParameter(i.UNPACK_ROW_LENGTH),se=t.getParameter(i.UNPACK_SKIP_PIXELS),_e=t.getParameter(i.UNPACK_SKIP_ROWS);t.pixelStorei(i.UNPACK_ROW_LENGTH,S.width);for(let k=0,re=ve.length;k<re;k++){let ne=ve[k],we=Math.floor(ne.start/4),xe=Math.ceil(ne.count/4),Se=we%S.width,Ge=Math.floor(we/S.width),et=xe,ue=1;t.pixelStorei(i.UNPACK_SKIP_PIXELS,Se),t.pixelStorei(i.UNPACK_SKIP_ROWS,Ge),t.texSubImage2D(i.TEXTURE_2D,0,Se,Ge,et,ue,Z,de,S.data)}L.clearUpdateRanges(),t.pixelStorei(i.UNPACK_ROW_LENGTH,te),t.pixelStorei(i.UNPACK_SKIP_PIXELS,se),t.pixelStorei(i.UNPACK_SKIP_ROWS,_e)}}function At(L,S,Z){let de=i.TEXTURE_2D;(S.isDataArrayTexture||S.isCompressedArrayTexture)&&(de=i.TEXTURE_2D_ARRAY),S.isData3DTexture&&(de=i.TEXTURE_3D);let oe=ot(L,S),ve=S.source;t.bindTexture(de,L.__webglTexture,i.TEXTURE0+Z);let ye=n.get(ve);if(ve.version!==ye.__version||oe===!0){if(t.activeTexture(i.TEXTURE0+Z),(typeof ImageBitmap<"u"&&S.image instanceof ImageBitmap)===!1){let ue=_t.getPrimaries(_t.workingColorSpace),ke=S.colorSpace===Ss?null:_t.getPrimaries(S.colorSpace),tt=S.colorSpace===Ss||ue===ke?i.NONE:i.BROWSER_DEFAULT_WEBGL;t.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,S.flipY),t.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,S.premultiplyAlpha),t.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,tt)}t.pixelStorei(i.UNPACK_ALIGNMENT,S.unpackAlignment);let se=y(S.image,!1,s.maxTextureSize);se=He(S,se);let _e=r.convert(S.format,S.colorSpace),k=r.convert(S.type),re=b(S.internalFormat,_e,k,S.normalized,S.colorSpace,S.isVideoTexture);qe(de,S);let ne,we=S.mipmaps,xe=S.isVideoTexture!==!0,Se=ye.__version===void 0||oe===!0,Ge=ve.dataReady,et=A(S,se);if(S.isDepthTexture)re=_(S.format===bs,S.type),Se&&(xe?t.texStorage2D(i.TEXTURE_2D,1,re,se.width,se.height):t.texImage2D(i.TEXTURE_2D,0,re,se.width,se.height,0,_e,k,null));else if(S.isDataTexture)if(we.length>0){xe&&Se&&t.texStorage2D(i.TEXTURE_2D,et,re,we[0].width,we[0].height);for(let ue=0,ke=we.length;ue<ke;ue++)ne=we[ue],xe?Ge&&t.texSubImage2D(i.TEXTURE_2D,ue,0,0,ne.width,ne.height,_e,k,ne.data):t.texImage2D(i.TEXTURE_2D,ue,re,ne.width,ne.height,0,_e,k,ne.data);S.generateMipmaps=!1}else xe?(Se&&t.texStorage2D(i.TEXTURE_2D,et,re,se.width,se.height),Ge&&bt(S,se,_e,k)):t.texImage2D(i.TEXTURE_2D,0,re,se.width,se.height,0,_e,k,se.data);else if(S.isCompressedTexture)if(S.isCompressedArrayTexture){xe&&Se&&t.texStorage3D(i.TEXTURE_2D_ARRAY,et,re,we[0].width,we[0].height,se.depth);for(let ue=0,ke=we.length;ue<ke;ue++)if(ne=we[ue],S.format!==Ui)if(_e!==null)if(xe){if(Ge)if(S.layerUpdates.size>0){let tt=Vu(ne.width,ne.height,S.format,S.type);for(let Ae of S.layerUpdates){let ht=ne.data.subarray(Ae*tt/ne.data.BYTES_PER_ELEMENT,(Ae+1)*tt/ne.data.BYTES_PER_ELEMENT);t.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ue,0,0,Ae,ne.width,ne.height,1,_e,ht)}}else t.compressedTexSubImage3D(i.TEXTURE_2D_ARRAY,ue,0,0,0,ne.width,ne.height,se.depth,_e,ne.data)}else t.compressedTexImage3D(i.TEXTURE_2D_ARRAY,ue,re,ne.width,ne.height,se.depth,0,ne.data,0,0);else Ye("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else xe?Ge&&t.texSubImage3D(i.TEXTURE_2D_ARRAY,ue,0,0,0,ne.width,ne.height,se.depth,_e,k,ne.data):t.texImage3D(i.TEXTURE_2D_ARRAY,ue,re,ne.width,ne.height,se.depth,0,_e,k,ne.data);S.layerUpdates.size>0&&S.clearLayerUpdates()}else{xe&&Se&&t.texStorage2D(i.TEXTURE_2D,et,re,we[0].width,we[0].height);for(let ue=0,ke=we.length;ue<ke;ue++)ne=we[ue],S.format!==Ui?_e!==null?xe?Ge&&t.compressedTexSubImage2D(i.TEXTURE_2D,ue,0,0,ne.width,ne.height,_e,ne.data):t.compressedTexImage2D(i.TEXTURE_2D,ue,re,ne.width,ne.height,0,ne.data):Ye("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):xe?Ge&&t.texSubImage2D(i.TEXTURE_2D,ue,0,0,ne.width,ne.height,_e,k,ne.data):t.texImage2D(i.TEXTURE_2D,ue,re,ne.width,ne.height,0,_e,k,ne.data)}else if(S.isDataArrayTexture)if(xe){if(Se&&t.texStorage3D(i.TEXTURE_2D_ARRAY,et,re,se.width,se.height,se.depth),Ge)if(S.layerUpdates.size>0){let ue=Vu(se.width,se.height,S.format,S.type);for(let ke of S.layerUpdates){let tt=se.data.subarray(ke*ue/se.data.BYTES_PER_ELEMENT,(ke+1)*ue/se.data.BYTES_PER_ELEMENT);t.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,ke,se.width,se.height,1,_e,k,tt)}S.clearLayerUpdates()}else t.texSubImage3D(i.TEXTURE_2D_ARRAY,0,0,0,0,se.width,se.height,se.depth,_e,k,se.data)}else t.texImage3D(i.TEXTURE_2D_ARRAY,0,re,se.width,se.height,se.depth,0,_e,k,se.data);else if(S.isData3DTexture)xe?(Se&&t.texStorage3D(i.TEXTURE_3D,et,re,se.width,se.height,se.depth),Ge&&t.texSubImage3D(i.TEXTURE_3D,0,0,0,0,se.width,se.height,se.depth,_e,k,se.data)):t.texImage3D(i.TEXTURE_3D,0,re,se.width,se.height,se.depth,0,_e,k,se.data);else if(S.isFramebufferTexture){if(Se)if(xe)t.texStorage2D(i.TEXTURE_2D,et,re,se.width,se.height);else{let ue=se.width,ke=se.height;for(let tt=0;tt<et;tt++)t.texImage2D(i.TEXTURE_2D,tt,re,ue,ke,0,_e,k,null),ue>>=1,ke>>=1}}else if(S.isHTMLTexture){if("texElementImage2D"in i){let ue=i.canvas;if(ue.hasAttribute("layoutsubtree")||ue.setAttribute("layoutsubtree","true"),se.parentNode!==ue){ue.appendChild(se),u.add(S),ue.onpaint=ke=>{let tt=ke.changedElements;for(let Ae of u)tt.includes(Ae.image)&&(Ae.needsUpdate=!0)},ue.requestPaint();return}if(i.texElementImage2D.length===3)i.texElementImage2D(i.TEXTURE_2D,i.RGBA8,se);else{let tt=i.RGBA,Ae=i.RGBA,ht=i.UNSIGNED_BYTE;i.texElementImage2D(i.TEXTURE_2D,0,tt,Ae,ht,se)}i.texParameteri(i.TEXTURE_2D,i.TEXTURE_MIN_FILTER,i.LINEAR),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_S,i.CLAMP_TO_EDGE),i.texParameteri(i.TEXTURE_2D,i.TEXTURE_WRAP_T,i.CLAMP_TO_EDGE)}}else if(we.length>0){if(xe&&Se){let ue=$e(we[0]);t.texStorage2D(i.TEXTURE_2D,et,re,ue.width,ue.height)}for(let ue=0,ke=we.length;ue<ke;ue++)ne=we[ue],xe?Ge&&t.texSubImage2D(i.TEXTURE_2D,ue,0,0,_e,k,ne):t.texImage2D(i.TEXTURE_2D,ue,re,_e,k,ne);S.generateMipmaps=!1}else if(xe){if(Se){let ue=$e(se);t.texStorage2D(i.TEXTURE_2D,et,re,ue.width,ue.height)}Ge&&t.texSubImage2D(i.TEXTURE_2D,0,0,0,_e,k,se)}else t.texImage2D(i.TEXTURE_2D,0,re,_e,k,se);C(S)&&S.mipmapsAutoUpdate===!0&&M(de),ye.__version=ve.version,S.onUpdate&&S.onUpdate(S)}L.__version=S.version}function sn(L,S,Z){if(S.image.length!==6)return;let de=ot(L,S),oe=S.source;t.bindTexture(i.TEXTURE_CUBE_MAP,L.__webglTexture,i.TEXTURE0+Z);let ve=n.get(oe);if(oe.version!==ve.__version||de===!0){t.activeTexture(i.TEXTURE0+Z);let ye=_t.getPrimaries(_t.workingColorSpace),te=S.colorSpace===Ss?null:_t.getPrimaries(S.colorSpace),se=S.colorSpace===Ss||ye===te?i.NONE:i.BROWSER_DEFAULT_WEBGL;t.pixelStorei(i.UNPACK_FLIP_Y_WEBGL,S.flipY),t.pixelStorei(i.UNPACK_PREMULTIPLY_ALPHA_WEBGL,S.premultiplyAlpha),t.pixelStorei(i.UNPACK_ALIGNMENT,S.unpackAlignment),t.pixelStorei(i.UNPACK_COLORSPACE_CONVERSION_WEBGL,se);let _e=S.isCompressedTexture||S.image[0].isCompressedTexture,k=S.image[0]&&S.image[0].isDataTexture,re=[];for(let Ae=0;Ae<6;Ae++)!_e&&!k?re[Ae]=y(S.image[Ae],!0,s.maxCubemapSize):re[Ae]=k?S.image[Ae].image:S.image[Ae],re[Ae]=He(S,re[Ae]);let ne=re[0],we=r.convert(S.format,S.colorSpace),xe=r.convert(S.type),Se=b(S.internalFormat,we,xe,S.normalized,S.colorSpace),Ge=S.isVideoTexture!==!0,et=ve.__version===void 0||de===!0,ue=oe.dataReady,ke=A(S,ne);qe(i.TEXTURE_CUBE_MAP,S);let tt;if(S.isDepthTexture){if(Se=_(S.format===bs,S.type),et)if(Ge)t.texStorage2D(i.TEXTURE_CUBE_MAP,1,Se,ne.width,ne.height);else for(let Ae=0;Ae<6;Ae++)t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Ae,0,Se,ne.width,ne.height,0,we,xe,null)}else if(_e){Ge&&et&&t.texStorage2D(i.TEXTURE_CUBE_MAP,ke,Se,ne.width,ne.height);for(let Ae=0;Ae<6;Ae++){tt=re[Ae].mipmaps;for(let ht=0;ht<tt.length;ht++){let Ht=tt[ht];S.format!==Ui?we!==null?Ge?ue&&t.compressedTexSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Ae,ht,0,0,Ht.width,Ht.height,we,Ht.data):t.compressedTexImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Ae,ht,Se,Ht.width,Ht.height,0,Ht.data):Ye("WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):Ge?ue&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Ae,ht,0,0,Ht.width,Ht.height,we,xe,Ht.data):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Ae,ht,Se,Ht.width,Ht.height,0,we,xe,Ht.data)}}}else{if(tt=S.mipmaps,Ge&&et){tt.length>0&&ke++;let Ae=$e(re[0]);t.texStorage2D(i.TEXTURE_CUBE_MAP,ke,Se,Ae.width,Ae.height)}for(let Ae=0;Ae<6;Ae++)if(k){Ge?ue&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Ae,0,0,0,re[Ae].width,re[Ae].height,we,xe,re[Ae].data):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Ae,0,Se,re[Ae].width,re[Ae].height,0,we,xe,re[Ae].data);for(let ht=0;ht<tt.length;ht++){let kn=tt[ht].image[Ae].image;Ge?ue&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Ae,ht+1,0,0,kn.width,kn.height,we,xe,kn.data):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Ae,ht+1,Se,kn.width,kn.height,0,we,xe,kn.data)}}else{Ge?ue&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Ae,0,0,0,we,xe,re[Ae]):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Ae,0,Se,we,xe,re[Ae]);for(let ht=0;ht<tt.length;ht++){let Ht=tt[ht];Ge?ue&&t.texSubImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Ae,ht+1,0,0,we,xe,Ht.image[Ae]):t.texImage2D(i.TEXTURE_CUBE_MAP_POSITIVE_X+Ae,ht+1,Se,we,xe,Ht.image[Ae])}}}C(S)&&S.mipmapsAutoUpdate===!0&&M(i.TEXTURE_CUBE_MAP),ve.__version=oe.version,S.onUpdate&&S.onUpdate(S)}L.__version=S.version}function Nt(L,S,Z,de,oe,ve){let ye=r.convert(Z.format,Z.colorSpace),te=r.convert(Z.type),se=b(Z.internalFormat,ye,te,Z.normalized,Z.colorSpace),_e=n.get(S),k=n.get(Z);if(k.__renderTarget=S,!_e.__hasExternalTextures){let re=Math.max(1,S.width>>ve),ne=Math.max(1,S.height>>ve);oe===i.TEXTURE_3D||oe===i.TEXTURE_2D_ARRAY?t.texImage3D(oe,ve,se,re,ne,S.depth,0,ye,te,null):t.texImage2D(oe,ve,se,re,ne,0,ye,te,null)}t.bindFramebuffer(i.FRAMEBUFFER,L),Me(S)?a.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,de,oe,k.__webglTexture,0,at(S)):(oe===i.TEXTURE_2D||oe>=i.TEXTURE_CUBE_MAP_POSITIVE_X&&oe<=i.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&i.framebufferTexture2D(i.FRAMEBUFFER,de,oe,k.__webglTexture,ve),t.bindFramebuffer(i.FRAMEBUFFER,null)}function yn(L,S,Z){if(i.bindRenderbuffer(i.RENDERBUFFER,L),S.depthBuffer){let de=S.depthTexture,oe=de&&de.isDepthTexture?de.type:null,ve=_(S.stencilBuffer,oe),ye=S.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;Me(S)?a.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,at(S),ve,S.width,S.height):Z?i.renderbufferStorageMultisample(i.RENDERBUFFER,at(S),ve,S.width,S.height):i.renderbufferStorage(i.RENDERBUFFER,ve,S.width,S.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,ye,i.RENDERBUFFER,L)}else{let de=S.textures;for(let oe=0;oe<de.length;oe++){let ve=de[oe],ye=r.convert(ve.format,ve.colorSpace),te=r.convert(ve.type),se=b(ve.internalFormat,ye,te,ve.normalized,ve.colorSpace);Me(S)?a.renderbufferStorageMultisampleEXT(i.RENDERBUFFER,at(S),se,S.width,S.height):Z?i.renderbufferStorageMultisample(i.RENDERBUFFER,at(S),se,S.width,S.height):i.renderbufferStorage(i.RENDERBUFFER,se,S.width,S.height)}}i.bindRenderbuffer(i.RENDERBUFFER,null)}function yt(L,S,Z){let de=S.isWebGLCubeRenderTarget===!0;if(t.bindFramebuffer(i.FRAMEBUFFER,L),!(S.depthTexture&&S.depthTexture.isDepthTexture))throw new Error("THREE.WebGLTextures: renderTarget.depthTexture must be an instance of THREE.DepthTexture.");let oe=n.get(S.depthTexture);oe.__renderTarget=S;let ve=de?S.depthTexture.image[0]:S.depthTexture.image;(!oe.__webglTexture||ve.width!==S.width||ve.height!==S.height)&&(ve.width=S.width,ve.height=S.height,S.depthTexture.needsUpdate=!0),de?pe(S.depthTexture,0):fe(S.depthTexture,0);let ye=oe.__webglTexture,te=at(S),se=de?i.TEXTURE_CUBE_MAP_POSITIVE_X+Z:i.TEXTURE_2D,_e=S.depthTexture.format===bs?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;if(S.depthTexture.format===ms)Me(S)?a.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,_e,se,ye,0,te):i.framebufferTexture2D(i.FRAMEBUFFER,_e,se,ye,0);else if(S.depthTexture.format===bs)Me(S)?a.framebufferTexture2DMultisampleEXT(i.FRAMEBUFFER,_e,se,ye,0,te):i.framebufferTexture2D(i.FRAMEBUFFER,_e,se,ye,0);else throw new Error("THREE.WebGLTextures: Unknown depthTexture format.")}function fn(L){let S=n.get(L),Z=L.isWebGLCubeRenderTarget===!0;if(S.__boundDepthTexture!==L.depthTexture){let de=L.depthTexture;if(S.__depthDisposeCallback&&S.__depthDisposeCallback(),de){let oe=()=>{delete S.__boundDepthTexture,delete S.__depthDisposeCallback,de.removeEventListener("dispose",oe)};de.addEventListener("dispose",oe),S.__depthDisposeCallback=oe}S.__boundDepthTexture=de}if(L.depthTexture&&!S.__autoAllocateDepthBuffer)if(Z)for(let de=0;de<6;de++)yt(S.__webglFramebuffer[de],L,de);else L.texture.mipmaps.length>0?yt(S.__webglFramebuffer[0],L,0):yt(S.__webglFramebuffer,L,0);else if(Z){S.__webglDepthbuffer=[];for(let de=0;de<6;de++)if(t.bindFramebuffer(i.FRAMEBUFFER,S.__webglFramebuffer[de]),S.__webglDepthbuffer[de]===void 0)S.__webglDepthbuffer[de]=i.createRenderbuffer(),yn(S.__webglDepthbuffer[de],L,!1);else{let oe=L.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,ve=S.__webglDepthbuffer[de];i.bindRenderbuffer(i.RENDERBUFFER,ve),i.framebufferRenderbuffer(i.FRAMEBUFFER,oe,i.RENDERBUFFER,ve)}}else if(L.texture.mipmaps.length>0?t.bindFramebuffer(i.FRAMEBUFFER,S.__webglFramebuffer[0]):t.bindFramebuffer(i.FRAMEBUFFER,S.__webglFramebuffer),S.__webglDepthbuffer===void 0)S.__webglDepthbuffer=i.createRenderbuffer(),yn(S.__webglDepthbuffer,L,!1);else{let oe=L.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,ve=S.__webglDepthbuffer;i.bindRenderbuffer(i.RENDERBUFFER,ve),i.framebufferRenderbuffer(i.FRAMEBUFFER,oe,i.RENDERBUFFER,ve)}t.bindFramebuffer(i.FRAMEBUFFER,null)}function Jt(L,S,Z){let de=n.get(L);S!==void 0&&Nt(de.__webglFramebuffer,L,L.texture,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,0),Z!==void 0&&fn(L)}function rn(L){let S=L.texture,Z=n.get(L),de=n.get(S);L.addEventListener("dispose",F),H(L);let oe=L.textures,ve=L.isWebGLCubeRenderTarget===!0,ye=oe.length>1;if(ye||(de.__webglTexture===void 0&&(de.__webglTexture=i.createTexture()),de.__version=S.version,o.memory.textures++),ve){Z.__webglFramebuffer=[];for(let te=0;te<6;te++)if(S.mipmaps.length>0){Z.__webglFramebuffer[te]=[];for(let se=0;se<S.mipmaps.length;se++)Z.__webglFramebuffer[te][se]=i.createFramebuffer()}else Z.__webglFramebuffer[te]=i.createFramebuffer()}else{if(S.mipmaps.length>0){Z.__webglFramebuffer=[];for(let te=0;te<S.mipmaps.length;te++)Z.__webglFramebuffer[te]=i.createFramebuffer()}else Z.__webglFramebuffer=i.createFramebuffer();if(ye)for(let te=0,se=oe.length;te<se;te++){let _e=n.get(oe[te]);_e.__webglTexture===void 0&&(_e.__webglTexture=i.createTexture(),o.memory.textures++)}if(L.samples>0&&Me(L)===!1){Z.__webglMultisampledFramebuffer=i.createFramebuffer(),Z.__webglColorRenderbuffer=[],t.bindFramebuffer(i.FRAMEBUFFER,Z.__webglMultisampledFramebuffer);for(let te=0;te<oe.length;te++){let se=oe[te];Z.__webglColorRenderbuffer[te]=i.createRenderbuffer(),i.bindRenderbuffer(i.RENDERBUFFER,Z.__webglColorRenderbuffer[te]);let _e=r.convert(se.format,se.colorSpace),k=r.convert(se.type),re=b(se.internalFormat,_e,k,se.normalized,se.colorSpace,L.isXRRenderTarget===!0),ne=at(L);i.renderbufferStorageMultisample(i.RENDERBUFFER,ne,re,L.width,L.height),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+te,i.RENDERBUFFER,Z.__webglColorRenderbuffer[te])}i.bindRenderbuffer(i.RENDERBUFFER,null),L.depthBuffer&&(Z.__webglDepthRenderbuffer=i.createRenderbuffer(),yn(Z.__webglDepthRenderbuffer,L,!0)),t.bindFramebuffer(i.FRAMEBUFFER,null)}}if(ve){t.bindTexture(i.TEXTURE_CUBE_MAP,de.__webglTexture),qe(i.TEXTURE_CUBE_MAP,S);for(let te=0;te<6;te++)if(S.mipmaps.length>0)for(let se=0;se<S.mipmaps.length;se++)Nt(Z.__webglFramebuffer[te][se],L,S,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+te,se);else Nt(Z.__webglFramebuffer[te],L,S,i.COLOR_ATTACHMENT0,i.TEXTURE_CUBE_MAP_POSITIVE_X+te,0);C(S)?M(i.TEXTURE_CUBE_MAP):S.mipmaps.length>0&&i.texParameteri(i.TEXTURE_CUBE_MAP,i.TEXTURE_MAX_LEVEL,S.mipmaps.length-1),t.unbindTexture()}else if(ye){for(let te=0,se=oe.length;te<se;te++){let _e=oe[te],k=n.get(_e),re=i.TEXTURE_2D;(L.isWebGL3DRenderTarget||L.isWebGLArrayRenderTarget)&&(re=L.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),t.bindTexture(re,k.__webglTexture),qe(re,_e),Nt(Z.__webglFramebuffer,L,_e,i.COLOR_ATTACHMENT0+te,re,0),C(_e)&&M(re)}t.unbindTexture()}else{let te=i.TEXTURE_2D;if((L.isWebGL3DRenderTarget||L.isWebGLArrayRenderTarget)&&(te=L.isWebGL3DRenderTarget?i.TEXTURE_3D:i.TEXTURE_2D_ARRAY),t.bindTexture(te,de.__webglTexture),qe(te,S),S.mipmaps.length>0)for(let se=0;se<S.mipmaps.length;se++)Nt(Z.__webglFramebuffer[se],L,S,i.COLOR_ATTACHMENT0,te,se);else Nt(Z.__webglFramebuffer,L,S,i.COLOR_ATTACHMENT0,te,0);C(S)?M(te):S.mipmaps.length>0&&i.texParameteri(te,i.TEXTURE_MAX_LEVEL,S.mipmaps.length-1),t.unbindTexture()}L.depthBuffer&&fn(L)}function z(L){let S=L.textures;for(let Z=0,de=S.length;Z<de;Z++){let oe=S[Z];if(C(oe)&&oe.mipmapsAutoUpdate===!0){let ve=R(L),ye=n.get(oe).__webglTexture;t.bindTexture(ve,ye),M(ve),t.unbindTexture()}}}let Re=[];function Je(L){if(L.samples>0){if(Me(L)===!1){let S=L.textures,Z=L.width,de=L.height,oe=i.COLOR_BUFFER_BIT,ve=L.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT,ye=n.get(L),te=S.length>1;if(te)for(let _e=0;_e<S.length;_e++)t.bindFramebuffer(i.FRAMEBUFFER,ye.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+_e,i.RENDERBUFFER,null),t.bindFramebuffer(i.FRAMEBUFFER,ye.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+_e,i.TEXTURE_2D,null,0);t.bindFramebuffer(i.READ_FRAMEBUFFER,ye.__webglMultisampledFramebuffer),L.texture.mipmaps.length>0?t.bindFramebuffer(i.DRAW_FRAMEBUFFER,ye.__webglFramebuffer[0]):t.bindFramebuffer(i.DRAW_FRAMEBUFFER,ye.__webglFramebuffer);for(let _e=0;_e<S.length;_e++){if(L.resolveDepthBuffer&&(L.depthBuffer&&(oe|=i.DEPTH_BUFFER_BIT),L.stencilBuffer&&L.resolveStencilBuffer&&(oe|=i.STENCIL_BUFFER_BIT)),te){i.framebufferRenderbuffer(i.READ_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.RENDERBUFFER,ye.__webglColorRenderbuffer[_e]);let k=n.get(S[_e]).__webglTexture;i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0,i.TEXTURE_2D,k,0)}i.blitFramebuffer(0,0,Z,de,0,0,Z,de,oe,i.NEAREST),c===!0&&(Re.length=0,Re.push(i.COLOR_ATTACHMENT0+_e),L.depthBuffer&&L.storeMultisampledDepthBuffer===!1&&Re.push(ve),i.invalidateFramebuffer(i.READ_FRAMEBUFFER,Re))}if(t.bindFramebuffer(i.READ_FRAMEBUFFER,null),t.bindFramebuffer(i.DRAW_FRAMEBUFFER,null),te)for(let _e=0;_e<S.length;_e++){t.bindFramebuffer(i.FRAMEBUFFER,ye.__webglMultisampledFramebuffer),i.framebufferRenderbuffer(i.FRAMEBUFFER,i.COLOR_ATTACHMENT0+_e,i.RENDERBUFFER,ye.__webglColorRenderbuffer[_e]);let k=n.get(S[_e]).__webglTexture;t.bindFramebuffer(i.FRAMEBUFFER,ye.__webglFramebuffer),i.framebufferTexture2D(i.DRAW_FRAMEBUFFER,i.COLOR_ATTACHMENT0+_e,i.TEXTURE_2D,k,0)}t.bindFramebuffer(i.DRAW_FRAMEBUFFER,ye.__webglMultisampledFramebuffer)}else if(L.depthBuffer&&L.storeMultisampledDepthBuffer===!1&&c){let S=L.stencilBuffer?i.DEPTH_STENCIL_ATTACHMENT:i.DEPTH_ATTACHMENT;i.invalidateFramebuffer(i.DRAW_FRAMEBUFFER,[S])}}}function at(L){return Math.min(s.maxSamples,L.samples)}function Me(L){let S=n.get(L);return L.samples>0&&e.has("WEBGL_multisampled_render_to_texture")===!0&&S.__useRenderToTexture!==!1}function Bt(L){let S=o.render.frame;d.get(L)!==S&&(d.set(L,S),L.update())}function He(L,S){let Z=L.colorSpace,de=L.format,oe=L.type;return L.isCompressedTexture===!0||L.isVideoTexture===!0||Z!==$o&&Z!==Ss&&(_t.getTransfer(Z)===Rt?(de!==Ui||oe!==Qn)&&Ye("WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):it("WebGLTextures: Unsupported texture color space:",Z)),S}function $e(L){return typeof HTMLImageElement<"u"&&L instanceof HTMLImageElement?(l.width=L.naturalWidth||L.width,l.height=L.naturalHeight||L.height):typeof VideoFrame<"u"&&L instanceof VideoFrame?(l.width=L.displayWidth,l.height=L.displayHeight):(l.width=L.width,l.height=L.height),l}this.allocateTextureUnit=he,this.resetTextureUnits=I,this.getTextureUnits=q,this.setTextureUnits=ie,this.setTexture2D=fe,this.setTexture2DArray=le,this.setTexture3D=me,this.setTextureCube=pe,this.rebindTextures=Jt,this.setupRenderTarget=rn,this.updateRenderTargetMipmap=z,this.updateMultisampleRenderTarget=Je,this.setupDepthRenderbuffer=fn,this.setupFrameBufferTexture=Nt,this.useMultisampledRTT=Me,this.dispose=V}function pS(i,e){function t(n,s=Ss){let r,o=_t.getTransfer(s);if(n===Qn)return i.UNSIGNED_BYTE;if(n===nc)return i.UNSIGNED_SHORT_4_4_4_4;if(n===ic)return i.UNSIGNED_SHORT_5_5_5_1;if(n===wu)return i.UNSIGNED_INT_5_9_9_9_REV;if(n===Eu)return i.UNSIGNED_INT_10F_11F_11F_REV;if(n===Su)return i.BYTE;if(n===Mu)return i.SHORT;if(n===ro)return i.UNSIGNED_SHORT;if(n===tc)return i.INT;if(n===Li)return i.UNSIGNED_INT;if(n===Di)return i.FLOAT;if(n===Ni)return i.HALF_FLOAT;if(n===Tu)return i.ALPHA;if(n===Au)return i.RGB;if(n===Ui)return i.RGBA;if(n===ms)return i.DEPTH_COMPONENT;if(n===bs)return i.DEPTH_STENCIL;if(n===Ru)return i.RED;if(n===sc)return i.RED_INTEGER;if(n===$s)return i.RG;if(n===rc)return i.RG_INTEGER;if(n===oc)return i.RGBA_INTEGER;if(n===ba||n===Sa||n===Ma||n===wa)if(o===Rt)if(r=e.get("WEBGL_compressed_texture_s3tc_srgb"),r!==null){if(n===ba)return r.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(n===Sa)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(n===Ma)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(n===wa)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(r=e.get("WEBGL_compressed_texture_s3tc"),r!==null){if(n===ba)return r.COMPRESSED_RGB_S3TC_DXT1_EXT;if(n===Sa)return r.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(n===Ma)return r.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(n===wa)return r.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(n===ac||n===lc||n===cc||n===hc)if(r=e.get("WEBGL_compressed_texture_pvrtc"),r!==null){if(n===ac)return r.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(n===lc)return r.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(n===cc)return r.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(n===hc)return r.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(n===uc||n===dc||n===fc||n===pc||n===mc||n===Ea||n===gc)if(r=e.get("WEBGL_compressed_texture_etc"),r!==null){if(n===uc||n===dc)return o===Rt?r.COMPRESSED_SRGB8_ETC2:r.COMPRESSED_RGB8_ETC2;if(n===fc)return o===Rt?r.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:r.COMPRESSED_RGBA8_ETC2_EAC;if(n===pc)return r.COMPRESSED_R11_EAC;if(n===mc)return r.COMPRESSED_SIGNED_R11_EAC;if(n===Ea)return r.COMPRESSED_RG11_EAC;if(n===gc)return r.COMPRESSED_SIGNED_RG11_EAC}else return null;if(n===_c||n===xc||n===vc||n===yc||n===bc||n===Sc||n===Mc||n===wc||n===Ec||n===Tc||n===Ac||n===Rc||n===Cc||n===Pc)if(r=e.get("WEBGL_compressed_texture_astc"),r!==null){if(n===_c)return o===Rt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:r.COMPRESSED_RGBA_ASTC_4x4_KHR;if(n===xc)return o===Rt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:r.COMPRESSED_RGBA_ASTC_5x4_KHR;if(n===vc)return o===Rt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:r.COMPRESSED_RGBA_ASTC_5x5_KHR;if(n===yc)return o===Rt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:r.COMPRESSED_RGBA_ASTC_6x5_KHR;if(n===bc)return o===Rt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:r.COMPRESSED_RGBA_ASTC_6x6_KHR;if(n===Sc)return o===Rt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:r.COMPRESSED_RGBA_ASTC_8x5_KHR;if(n===Mc)return o===Rt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:r.COMPRESSED_RGBA_ASTC_8x6_KHR;if(n===wc)return o===Rt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:r.COMPRESSED_RGBA_ASTC_8x8_KHR;if(n===Ec)return o===Rt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:r.COMPRESSED_RGBA_ASTC_10x5_KHR;if(n===Tc)return o===Rt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:r.COMPRESSED_RGBA_ASTC_10x6_KHR;if(n===Ac)return o===Rt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:r.COMPRESSED_RGBA_ASTC_10x8_KHR;if(n===Rc)return o===Rt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:r.COMPRESSED_RGBA_ASTC_10x10_KHR;if(n===Cc)return o===Rt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:r.COMPRESSED_RGBA_ASTC_12x10_KHR;if(n===Pc)return o===Rt?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:r.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(n===Ic||n===Lc||n===Dc)if(r=e.get("EXT_texture_compression_bptc"),r!==null){if(n===Ic)return o===Rt?r.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:r.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(n===Lc)return r.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(n===Dc)return r.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(n===Nc||n===Uc||n===Ta||n===Fc)if(r=e.get("EXT_texture_compression_rgtc"),r!==null){if(n===Nc)return r.COMPRESSED_RED_RGTC1_EXT;if(n===Uc)return r.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(n===Ta)return r.COMPRESSED_RED_GREEN_RGTC2_EXT;if(n===Fc)return r.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return n===cr?i.UNSIGNED_INT_24_8:i[n]!==void 0?i[n]:null}return{convert:t}}var mS=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,gS=`
uniform sampler2DArray depthColor;
uniform float depthWidth;
uniform float depthHeight;

void main() {

	vec2 coord = vec2( gl_FragCoord.x / depthWidth, gl_FragCoord.y / depthHeight );

	if ( coord.x >= 1.0 ) {

		gl_FragDepth = texture( depthColor, vec3( coord.x - 1.0, coord.y, 1 ) ).r;

	} else {

		gl_FragDepth = texture( depthColor, vec3( coord.x, coord.y, 0 ) ).r;

	}

}`,td=class{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(e,t){if(this.texture===null){let n=new ia(e.texture);(e.depthNear!==t.depthNear||e.depthFar!==t.depthFar)&&(this.depthNear=e.depthNear,this.depthFar=e.depthFar),this.texture=n}}getMesh(e){if(this.texture!==null&&this.mesh===null){let t=e.cameras[0].viewport,n=new yi({vertexShader:mS,fragmentShader:gS,uniforms:{depthColor:{value:this.texture},depthWidth:{value:t.z},depthHeight:{value:t.w}}});this.mesh=new Pn(new sa(20,20),n)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}},nd=class extends Ci{constructor(e,t){super();let n=this,s=null,r=1,o=null,a="local-floor",c=1,l=null,d=null,u=null,h=null,m=null,g=null,v=typeof XRWebGLBinding<"u",p=new td,f={},y=t.getContextAttributes(),C=null,M=null,R=[],b=[],_=new je,A=null,H=null,O=new $n;O.viewport=new Ct;let T=new $n;T.viewport=new Ct;let F=[O,T],B=new Jl,D=null,V=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(Q){let fe=R[Q];return fe===void 0&&(fe=new Kr,R[Q]=fe),fe.getTargetRaySpace()},this.getControllerGrip=function(Q){let fe=R[Q];return fe===void 0&&(fe=new Kr,R[Q]=fe),fe.getGripSpace()},this.getHand=function(Q){let fe=R[Q];return fe===void 0&&(fe=new Kr,R[Q]=fe),fe.getHandSpace()};function Y(Q){let fe=b.indexOf(Q.inputSource);if(fe===-1)return;let le=R[fe];le!==void 0&&(le.update(Q.inputSource,Q.frame,l||o),le.dispatchEvent({type:Q.type,data:Q.inputSource}))}function $(){s.removeEventListener("select",Y),s.removeEventListener("selectstart",Y),s.removeEventListener("selectend",Y),s.removeEventListener("squeeze",Y),s.removeEventListener("squeezestart",Y),s.removeEventListener("squeezeend",Y),s.removeEventListener("end",$),s.removeEventListener("inputsourceschange",ce);for(let Q=0;Q<R.length;Q++){let fe=b[Q];fe!==null&&(b[Q]=null,R[Q].disconnect(fe))}D=null,V=null,p.reset();for(let Q in f)delete f[Q];if(e.setRenderTarget(C),m=null,h=null,u=null,s=null,M=null,he.stop(),n.isPresenting=!1,e.setPixelRatio(A),e.setSize(_.width,_.height,!1),H!==null){let Q=H.camera;Q.fov=H.fov,Q.zoom=H.zoom,Q.updateProjectionMatrix(),H=null}n.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(Q){r=Q,n.isPresenting===!0&&Ye("WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(Q){a=Q,n.isPresenting===!0&&Ye("WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return l||o},this.setReferenceSpace=function(Q){l=Q},this.getBaseLayer=function(){return h!==null?h:m},this.getBinding=function(){return u===null&&v&&(u=new XRWebGLBinding(s,t)),u},this.getFrame=function(){return g},this.getSession=function(){return s},this.setSession=async function(Q){if(s=Q,s!==null){if(C=e.getRenderTarget(),s.addEventListener("select",Y),s.addEventListener("selectstart",Y),s.addEventListener("selectend",Y),s.addEventListener("squeeze",Y),s.addEventListener("squeezestart",Y),s.addEventListener("squeezeend",Y),s.addEventListener("end",$),s.addEventListener("inputsourceschange",ce),y.xrCompatible!==!0&&await t.makeXRCompatible(),A=e.getPixelRatio(),e.getSize(_),v&&"createProjectionLayer"in XRWebGLBinding.prototype){let le=null,me=null,pe=null;y.depth&&(pe=y.stencil?t.DEPTH24_STENCIL8:t.DEPTH_COMPONENT24,le=y.stencil?bs:ms,me=y.stencil?cr:Li);let De={colorFormat:t.RGBA8,depthFormat:pe,scaleFactor:r};u=this.getBinding(),h=u.createProjectionLayer(De),s.updateRenderState({layers:[h]}),e.setPixelRatio(1),e.setSize(h.textureWidth,h.textureHeight,!1),M=new hi(h.textureWidth,h.textureHeight,{format:Ui,type:Qn,depthTexture:new vs(h.textureWidth,h.textureHeight,me,void 0,void 0,void 0,void 0,void 0,void 0,le),stencilBuffer:y.stencil,colorSpace:e.outputColorSpace,samples:y.antialias?4:0,resolveDepthBuffer:h.ignoreDepthValues===!1,resolveStencilBuffer:h.ignoreDepthValues===!1,storeMultisampledDepthBuffer:h.ignoreDepthValues===!1,storeMultisampledStencilBuffer:h.ignoreDepthValues===!1})}else{let le={antialias:y.antialias,alpha:!0,depth:y.depth,stencil:y.stencil,framebufferScaleFactor:r};m=new XRWebGLLayer(s,t,le),s.updateRenderState({baseLayer:m}),e.setPixelRatio(1),e.setSize(m.framebufferWidth,m.framebufferHeight,!1),M=new hi(m.framebufferWidth,m.framebufferHeight,{format:Ui,type:Qn,colorSpace:e.outputColorSpace,stencilBuffer:y.stencil,resolveDepthBuffer:m.ignoreDepthValues===!1,resolveStencilBuffer:m.ignoreDepthValues===!1,storeMultisampledDepthBuffer:m.ignoreDepthValues===!1,storeMultisampledStencilBuffer:m.ignoreDepthValues===!1})}M.isXRRenderTarget=!0,this.setFoveation(c),l=null,o=await s.requestReferenceSpace(a),he.setContext(s),he.start(),n.isPresenting=!0,n.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(s!==null)return s.environmentBlendMode},this.getDepthTexture=function(){return p.getDepthTexture()};function ce(Q){for(let fe=0;fe<Q.removed.length;fe++){let le=Q.removed[fe],me=b.indexOf(le);me>=0&&(b[me]=null,R[me].disconnect(le))}for(let fe=0;fe<Q.added.length;fe++){let le=Q.added[fe],me=b.indexOf(le);if(me===-1){for(let De=0;De<R.length;De++)if(De>=b.length){b.push(le),me=De;break}else if(b[De]===null){b[De]=le,me=De;break}if(me===-1)break}let pe=R[me];pe&&pe.connect(le)}}function P(Q,fe){fe===null?Q.matrixWorld.copy(Q.matrix):Q.matrixWorld.multiplyMatrices(fe.matrixWorld,Q.matrix),Q.matrixWorldInverse.copy(Q.matrixWorld).invert()}this.updateCamera=function(Q){if(s===null)return;let fe=Q.near,le=Q.far;p.texture!==null&&(p.depthNear>0&&(fe=p.depthNear),p.depthFar>0&&(le=p.depthFar)),B.near=T.near=O.near=fe,B.far=T.far=O.far=le,(D!==B.near||V!==B.far)&&(s.updateRenderState({depthNear:B.near,depthFar:B.far}),D=B.near,V=B.far),B.layers.mask=Q.layers.mask|6,O.layers.mask=B.layers.mask&-5,T.layers.mask=B.layers.mask&-3;let me=Q.parent,pe=B.cameras;P(B,me);for(let De=0;De<pe.length;De++)P(pe[De],me);B.projectionMatrix.copy(O.projectionMatrix),B.projectionMatrixInverse.copy(O.projectionMatrixInverse),H===null&&Q.isPerspectiveCamera&&(H={camera:Q,fov:Q.fov,zoom:Q.zoom}),I(Q,B,me)};function I(Q,fe,le){le===null?Q.matrix.copy(fe.matrixWorld):(Q.matrix.copy(le.matrixWorld),Q.matrix.invert(),Q.matrix.multiply(fe.matrixWorld)),Q.matrix.decompose(Q.position,Q.quaternion,Q.scale),Q.updateMatrixWorld(!0),Q.projectionMatrix.copy(fe.projectionMatrix),Q.projectionMatrixInverse.copy(fe.projectionMatrixInverse),Q.isPerspectiveCamera&&(Q.fov=Zr*2*Math.atan(1/Q.projectionMatrix.elements[5]),Q.zoom=1)}this.getCamera=function(){return B},this.getFoveation=function(){if(!(h===null&&m===null))return c},this.setFoveation=function(Q){c=Q,h!==null&&(h.fixedFoveation=Q),m!==null&&m.fixedFoveation!==void 0&&(m.fixedFoveation=Q)},this.hasDepthSensing=function(){return p.texture!==null},this.getDepthSensingMesh=function(){return p.getMesh(B)},this.getCameraTexture=function(Q){return f[Q]};let q=null;function ie(Q,fe){if(d=fe.getViewerPose(l||o),g=fe,d!==null){let le=d.views;m!==null&&(e.setRenderTargetFramebuffer(M,m.framebuffer),e.setRenderTarget(M));let me=!1;le.length!==B.cameras.length&&(B.cameras.length=0,me=!0);for(let Ne=0;Ne<le.length;Ne++){let qe=le[Ne],ot=null;if(m!==null)ot=m.getViewport(qe);else{let bt=u.getViewSubImage(h,qe);ot=bt.viewport,Ne===0&&(e.setRenderTargetTextures(M,bt.colorTexture,bt.depthStencilTexture),e.setRenderTarget(M))}let Qe=F[Ne];Qe===void 0&&(Qe=new $n,Qe.layers.enable(Ne),Qe.viewport=new Ct,F[Ne]=Qe),Qe.matrix.fromArray(qe.transform.matrix),Qe.matrix.decompose(Qe.position,Qe.quaternion,Qe.scale),Qe.projectionMatrix.fromArray(qe.projectionMatrix),Qe.projectionMatrixInverse.copy(Qe.projectionMatrix).invert(),Qe.viewport.set(ot.x,ot.y,ot.width,ot.height),Ne===0&&(B.matrix.copy(Qe.matrix),B.matrix.decompose(B.position,B.quaternion,B.scale)),me===!0&&B.cameras.push(Qe)}let pe=s.enabledFeatures;if(pe&&pe.includes("depth-sensing")&&s.depthUsage=="gpu-optimized"&&v){u=n.getBinding();let Ne=u.getDepthInformation(le[0]);Ne&&Ne.isValid&&Ne.texture&&p.init(Ne,s.renderState)}if(pe&&pe.includes("camera-access")&&v){e.state.unbindTexture(),u=n.getBinding();for(let Ne=0;Ne<le.length;Ne++){let qe=le[Ne].camera;if(qe){let ot=f[qe];ot||(ot=new ia,f[qe]=ot);let Qe=u.getCameraImage(qe);ot.sourceTexture=Qe}}}}for(let le=0;le<R.length;le++){let me=b[le],pe=R[le];me!==null&&pe!==void 0&&pe.update(me,fe,l||o)}q&&q(Q,fe),fe.detectedPlanes&&n.dispatchEvent({type:"planesdetected",data:fe}),g=null}let he=new nm;he.setAnimationLoop(ie),this.setAnimationLoop=function(Q){q=Q},this.dispose=function(){}}},_S=new kt,dm=new st;dm.set(-1,0,0,0,1,0,0,0,1);function xS(i,e){function t(p,f){p.matrixAutoUpdate===!0&&p.updateMatrix(),f.value.copy(p.matrix)}function n(p,f){f.color.getRGB(p.fogColor.value,Bu(i)),f.isFog?(p.fogNear.value=f.near,p.fogFar.value=f.far):f.isFogExp2&&(p.fogDensity.value=f.density)}function s(p,f,y,C,M){f.isNodeMaterial?f.uniformsNeedUpdate=!1:f.isMeshBasicMaterial?r(p,f):f.isMeshLambertMaterial?(r(p,f),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)):f.isMeshToonMaterial?(r(p,f),u(p,f)):f.isMeshPhongMaterial?(r(p,f),d(p,f),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)):f.isMeshStandardMaterial?(r(p,f),h(p,f),f.isMeshPhysicalMaterial&&m(p,f,M)):f.isMeshMatcapMaterial?(r(p,f),g(p,f)):f.isMeshDepthMaterial?r(p,f):f.isMeshDistanceMaterial?(r(p,f),v(p,f)):f.isMeshNormalMaterial?r(p,f):f.isLineBasicMaterial?(o(p,f),f.isLineDashedMaterial&&a(p,f)):f.isPointsMaterial?c(p,f,y,C):f.isSpriteMaterial?l(p,f):f.isShadowMaterial?(p.color.value.copy(f.color),p.opacity.value=f.opacity):f.isShaderMaterial&&(f.uniformsNeedUpdate=!1)}function r(p,f){p.opacity.value=f.opacity,f.color&&p.diffuse.value.copy(f.color),f.emissive&&p.emissive.value.copy(f.emissive).multiplyScalar(f.emissiveIntensity),f.map&&(p.map.value=f.map,t(f.map,p.mapTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,t(f.alphaMap,p.alphaMapTransform)),f.bumpMap&&(p.bumpMap.value=f.bumpMap,t(f.bumpMap,p.bumpMapTransform),p.bumpScale.value=f.bumpScale,f.side===Yn&&(p.bumpScale.value*=-1)),f.normalMap&&(p.normalMap.value=f.normalMap,t(f.normalMap,p.normalMapTransform),p.normalScale.value.copy(f.normalScale),f.side===Yn&&p.normalScale.value.negate()),f.displacementMap&&(p.displacementMap.value=f.displacementMap,t(f.displacementMap,p.displacementMapTransform),p.displacementScale.value=f.displacementScale,p.displacementBias.value=f.displacementBias),f.emissiveMap&&(p.emissiveMap.value=f.emissiveMap,t(f.emissiveMap,p.emissiveMapTransform)),f.specularMap&&(p.specularMap.value=f.specularMap,t(f.specularMap,p.specularMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest);let y=e.get(f),C=y.envMap,M=y.envMapRotation;C&&(p.envMap.value=C,p.envMapRotation.value.setFromMatrix4(_S.makeRotationFromEuler(M)).transpose(),C.isCubeTexture&&C.isRenderTargetTexture===!1&&p.envMapRotation.value.premultiply(dm),p.reflectivity.value=f.reflectivity,p.ior.value=f.ior,p.refractionRatio.value=f.refractionRatio),f.lightMap&&(p.lightMap.value=f.lightMap,p.lightMapIntensity.value=f.lightMapIntensity,t(f.lightMap,p.lightMapTransform)),f.aoMap&&(p.aoMap.value=f.aoMap,p.aoMapIntensity.value=f.aoMapIntensity,t(f.aoMap,p.aoMapTransform))}function o(p,f){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,f.map&&(p.map.value=f.map,t(f.map,p.mapTransform))}function a(p,f){p.dashSize.value=f.dashSize,p.totalSize.value=f.dashSize+f.gapSize,p.scale.value=f.scale}function c(p,f,y,C){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,p.size.value=f.size*y,p.scale.value=C*.5,f.map&&(p.map.value=f.map,t(f.map,p.uvTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,t(f.alphaMap,p.alphaMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest)}function l(p,f){p.diffuse.value.copy(f.color),p.opacity.value=f.opacity,p.rotation.value=f.rotation,f.map&&(p.map.value=f.map,t(f.map,p.mapTransform)),f.alphaMap&&(p.alphaMap.value=f.alphaMap,t(f.alphaMap,p.alphaMapTransform)),f.alphaTest>0&&(p.alphaTest.value=f.alphaTest)}function d(p,f){p.specular.value.copy(f.specular),p.shininess.value=Math.max(f.shininess,1e-4)}function u(p,f){f.gradientMap&&(p.gradientMap.value=f.gradientMap)}function h(p,f){p.metalness.value=f.metalness,f.metalnessMap&&(p.metalnessMap.value=f.metalnessMap,t(f.metalnessMap,p.metalnessMapTransform)),p.roughness.value=f.roughness,f.roughnessMap&&(p.roughnessMap.value=f.roughnessMap,t(f.roughnessMap,p.roughnessMapTransform)),f.envMap&&(p.envMapIntensity.value=f.envMapIntensity)}function m(p,f,y){p.ior.value=f.ior,f.diffuseRoughness>0&&(p.diffuseRoughness.value=f.diffuseRoughness,f.diffuseRoughnessMap&&(p.diffuseRoughnessMap.value=f.diffuseRoughnessMap,t(f.diffuseRoughnessMap,p.diffuseRoughnessMapTransform))),f.sheen>0&&(p.sheenColor.value.copy(f.sheenColor).multiplyScalar(f.sheen),p.sheenRoughness.value=f.sheenRoughness,f.sheenColorMap&&(p.sheenColorMap.value=f.sheenColorMap,t(f.sheenColorMap,p.sheenColorMapTransform)),f.sheenRoughnessMap&&(p.sheenRoughnessMap.value=f.sheenRoughnessMap,t(f.sheenRoughnessMap,p.sheenRoughnessMapTransform))),f.clearcoat>0&&(p.clearcoat.value=f.clearcoat,p.clearcoatRoughness.value=f.clearcoatRoughness,f.clearcoatMap&&(p.clearcoatMap.value=f.clearcoatMap,t(f.clearcoatMap,p.clearcoatMapTransform)),f.clearcoatRoughnessMap&&(p.clearcoatRoughnessMap.value=f.clearcoatRoughnessMap,t(f.clearcoatRoughnessMap,p.clearcoatRoughnessMapTransform)),f.clearcoatNormalMap&&(p.clearcoatNormalMap.value=f.clearcoatNormalMap,t(f.clearcoatNormalMap,p.clearcoatNormalMapTransform),p.clearcoatNormalScale.value.copy(f.clearcoatNormalScale),f.side===Yn&&p.clearcoatNormalScale.value.negate())),f.dispersion>0&&(p.dispersion.value=f.dispersion),f.retroreflectivity>0&&(p.retroreflectivity.value=f.retroreflectivity),f.iridescence>0&&(p.iridescence.value=f.iridescence,p.iridescenceIOR.value=f.iridescenceIOR,p.iridescenceThicknessMinimum.value=f.iridescenceThicknessMinimum,p.iridescenceThicknessMaximum.value=f.iridescenceThicknessMaximum,f.iridescenceMap&&(p.iridescenceMap.value=f.iridescenceMap,t(f.iridescenceMap,p.iridescenceMapTransform)),f.iridescenceThicknessMap&&(p.iridescenceThicknessMap.value=f.iridescenceThicknessMap,t(f.iridescenceThicknessMap,p.iridescenceThicknessMapTransform))),f.transmission>0&&(p.transmission.value=f.transmission,p.transmissionSamplerMap.value=y.texture,p.transmissionSamplerSize.value.set(y.width,y.height),f.transmissionMap&&(p.transmissionMap.value=f.transmissionMap,t(f.transmissionMap,p.transmissionMapTransform)),p.thickness.value=f.thickness,f.thicknessMap&&(p.thicknessMap.value=f.thicknessMap,t(f.thicknessMap,p.thicknessMapTransform)),p.attenuationDistance.value=f.attenuationDistance,p.attenuationColor.value.copy(f.attenuationColor)),f.anisotropy>0&&(p.anisotropyVector.value.set(f.anisotropy*Math.cos(f.anisotropyRotation),f.anisotropy*Math.sin(f.anisotropyRotation)),f.anisotropyMap&&(p.anisotropyMap.value=f.anisotropyMap,t(f.anisotropyMap,p.anisotropyMapTransform))),p.specularIntensity.value=f.specularIntensity,p.specularColor.value.copy(f.specularColor),f.specularColorMap&&(p.specularColorMap.value=f.specularColorMap,t(f.specularColorMap,p.specularColorMapTransform)),f.specularIntensityMap&&(p.specularIntensityMap.value=f.specularIntensityMap,t(f.specularIntensityMap,p.specularIntensityMapTransform))}function g(p,f){f.matcap&&(p.matcap.value=f.matcap)}function v(p,f){let y=e.get(f).light;p.referencePosition.value.setFromMatrixPosition(y.matrixWorld),p.nearDistance.value=y.shadow.camera.near,p.farDistance.value=y.shadow.camera.far}return{refreshFogUniforms:n,refreshMaterialUniforms:s}}function vS(i,e,t,n){let s={},r={};function o(y,C){let M=C.program;n.uniformBlockBinding(y,M,s[y.id])}function a(y,C){let M=s[y.id];M===void 0&&(g(y),M=c(y),s[y.id]=M,y.addEventListener("dispose",p));let R=C.program;n.updateUBOMapping(y,R);let b=e.render.frame;r[y.id]!==b&&(l(y),r[y.id]=b)}function c(y){let C=i.createBuffer(),M=y.__size,R=y.usage;return i.bindBuffer(i.UNIFORM_BUFFER,C),i.bufferData(i.UNIFORM_BUFFER,M,R),i.bindBuffer(i.UNIFORM_BUFFER,null),C}function l(y){let C=s[y.id],M=y.uniforms,R=y.__cache;i.bindBuffer(i.UNIFORM_BUFFER,C);for(let b=0,_=M.length;b<_;b++){let A=M[b];if(Array.isArray(A))for(let H=0,O=A.length;H<O;H++)d(A[H],b,H,R);else d(A,b,0,R)}i.bindBuffer(i.UNIFORM_BUFFER,null)}function d(y,C,M,R){if(h(y,C,M,R)===!0){let b=y.__offset,_=y.value;if(Array.isArray(_)){let A=0;for(let H=0;H<_.length;H++){let O=_[H],T=v(O,!0);u(O,y.__data,A),A+=T.storage/Float32Array.BYTES_PER_ELEMENT}}else u(_,y.__data,0);i.bufferSubData(i.UNIFORM_BUFFER,b,y.__data)}}function u(y,C,M){typeof y=="number"||typeof y=="boolean"?C[M]=y:y.isMatrix3?(C[M]=y.elements[0],C[M+1]=y.elements[1],C[M+2]=y.elements[2],C[M+3]=0,C[M+4]=y.elements[3],C[M+5]=y.elements[4],C[M+6]=y.elements[5],C[M+7]=0,C[M+8]=y.elements[6],C[M+9]=y.elements[7],C[M+10]=y.elements[8],C[M+11]=0):ArrayBuffer.isView(y)?C.set(y.subarray(0,C.length-M),M):y.toArray(C,M)}function h(y,C,M,R){let b=y.value,_=C+"_"+M;if(Array.isArray(b)){R[_]===void 0&&(R[_]=[]);let A=R[_],H=!1;for(let O=0;O<b.length;O++)m(b[O],A,O)===!0&&(H=!0);return H}return m(b,R,_)}function m(y,C,M){if(C[M]===void 0)return typeof y=="number"||typeof y=="boolean"?C[M]=y:ArrayBuffer.isView(y)?C[M]=y.slice():C[M]=y.clone(),!0;{let R=C[M];if(typeof y=="number"||typeof y=="boolean"){if(R!==y)return C[M]=y,!0}else{if(ArrayBuffer.isView(y))return!0;if(R.equals(y)===!1)return R.copy(y),!0}}return!1}function g(y){let C=y.uniforms,M=0,R=16;for(let _=0,A=C.length;_<A;_++){let H=Array.isArray(C[_])?C[_]:[C[_]];for(let O=0,T=H.length;O<T;O++){let F=H[O],B=Array.isArray(F.value)?F.value:[F.value],D=Array.isArray(C[_])||Array.isArray(F.value),V=M;for(let $=0,ce=B.length;$<ce;$++){let P=B[$],I=v(P,D),q=M%R,ie=q%I.boundary,he=q+ie;M+=ie,he!==0&&R-he<I.storage&&(M+=R-he),$===0&&(V=M),M+=I.storage}let Y=F.type==="int"?Int32Array:F.type==="uint"?Uint32Array:Float32Array;F.__data=new Y((M-V)/Float32Array.BYTES_PER_ELEMENT),F.__offset=V}}let b=M%R;return b>0&&(M+=R-b),y.__size=M,y.__cache={},this}function v(y,C){let M={boundary:0,storage:0};return typeof y=="number"||typeof y=="boolean"?(M.boundary=4,M.storage=4):y.isVector2?(M.boundary=8,M.storage=8):y.isVector3||y.isColor?(M.boundary=16,M.storage=12):y.isVector4?(M.boundary=16,M.storage=16):y.isMatrix3?(M.boundary=16,M.storage=48):y.isMatrix4?(M.boundary=16,M.storage=64):y.isTexture?Ye("WebGLRenderer: Texture samplers can not be part of an uniforms group."):ArrayBuffer.isView(y)?(M.boundary=16,M.storage=y.byteLength):Ye("WebGLRenderer: Unsupported uniform value type.",y),C===!0&&(M.boundary=16,M.storage=Math.ceil(M.storage/16)*16),M}function p(y){let C=y.target;C.removeEventListener("dispose",p),i.deleteBuffer(s[C.id]),delete s[C.id],delete r[C.id]}function f(){for(let y in s)i.deleteBuffer(s[y]);s={},r={}}return{bind:o,update:a,dispose:f}}var yS=new Uint16Array([12469,15057,12620,14925,13266,14620,13807,14376,14323,13990,14545,13625,14713,13328,14840,12882,14931,12528,14996,12233,15039,11829,15066,11525,15080,11295,15085,10976,15082,10705,15073,10495,13880,14564,13898,14542,13977,14430,14158,14124,14393,13732,14556,13410,14702,12996,14814,12596,14891,12291,14937,11834,14957,11489,14958,11194,14943,10803,14921,10506,14893,10278,14858,9960,14484,14039,14487,14025,14499,13941,14524,13740,14574,13468,14654,13106,14743,12678,14818,12344,14867,11893,14889,11509,14893,11180,14881,10751,14852,10428,14812,10128,14765,9754,14712,9466,14764,13480,14764,13475,14766,13440,14766,13347,14769,13070,14786,12713,14816,12387,14844,11957,14860,11549,14868,11215,14855,10751,14825,10403,14782,10044,14729,9651,14666,9352,14599,9029,14967,12835,14966,12831,14963,12804,14954,12723,14936,12564,14917,12347,14900,11958,14886,11569,14878,11247,14859,10765,14828,10401,14784,10011,14727,9600,14660,9289,14586,8893,14508,8533,15111,12234,15110,12234,15104,12216,15092,12156,15067,12010,15028,11776,14981,11500,14942,11205,14902,10752,14861,10393,14812,9991,14752,9570,14682,9252,14603,8808,14519,8445,14431,8145,15209,11449,15208,11451,15202,11451,15190,11438,15163,11384,15117,11274,15055,10979,14994,10648,14932,10343,14871,9936,14803,9532,14729,9218,14645,8742,14556,8381,14461,8020,14365,7603,15273,10603,15272,10607,15267,10619,15256,10631,15231,10614,15182,10535,15118,10389,15042,10167,14963,9787,14883,9447,14800,9115,14710,8665,14615,8318,14514,7911,14411,7507,14279,7198,15314,9675,15313,9683,15309,9712,15298,9759,15277,9797,15229,9773,15166,9668,15084,9487,14995,9274,14898,8910,14800,8539,14697,8234,14590,7790,14479,7409,14367,7067,14178,6621,15337,8619,15337,8631,15333,8677,15325,8769,15305,8871,15264,8940,15202,8909,15119,8775,15022,8565,14916,8328,14804,8009,14688,7614,14569,7287,14448,6888,14321,6483,14088,6171,15350,7402,15350,7419,15347,7480,15340,7613,15322,7804,15287,7973,15229,8057,15148,8012,15046,7846,14933,7611,14810,7357,14682,7069,14552,6656,14421,6316,14251,5948,14007,5528,15356,5942,15356,5977,15353,6119,15348,6294,15332,6551,15302,6824,15249,7044,15171,7122,15070,7050,14949,6861,14818,6611,14679,6349,14538,6067,14398,5651,14189,5311,13935,4958,15359,4123,15359,4153,15356,4296,15353,4646,15338,5160,15311,5508,15263,5829,15188,6042,15088,6094,14966,6001,14826,5796,14678,5543,14527,5287,14377,4985,14133,4586,13869,4257,15360,1563,15360,1642,15358,2076,15354,2636,15341,3350,15317,4019,15273,4429,15203,4732,15105,4911,14981,4932,14836,4818,14679,4621,14517,4386,14359,4156,14083,3795,13808,3437,15360,122,15360,137,15358,285,15355,636,15344,1274,15322,2177,15281,2765,15215,3223,15120,3451,14995,3569,14846,3567,14681,3466,14511,3305,14344,3121,14037,2800,13753,2467,15360,0,15360,1,15359,21,15355,89,15346,253,15325,479,15287,796,15225,1148,15133,1492,15008,1749,14856,1882,14685,1886,14506,1783,14324,1608,13996,1398,13702,1183]),Ki=null;function bS(){return Ki===null&&(Ki=new Ll(yS,16,16,$s,Ni),Ki.name="DFG_LUT",Ki.minFilter=Xn,Ki.magFilter=Xn,Ki.wrapS=qi,Ki.wrapT=qi,Ki.generateMipmaps=!1,Ki.needsUpdate=!0),Ki}var Hc=class{constructor(e={}){let{canvas:t=Rp(),context:n=null,depth:s=!0,stencil:r=!1,alpha:o=!1,antialias:a=!1,premultipliedAlpha:c=!0,preserveDrawingBuffer:l=!1,powerPreference:d="default",failIfMajorPerformanceCaveat:u=!1,reversedDepthBuffer:h=!1,outputBufferType:m=Qn}=e;this.isWebGLRenderer=!0;let g;if(n!==null){if(typeof WebGLRenderingContext<"u"&&n instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");g=n.getContextAttributes().alpha}else g=o;let v=m,p=new Set([oc,rc,sc]),f=new Set([Qn,Li,ro,cr,nc,ic]),y=new Uint32Array(4),C=new Int32Array(4),M={textures:[],min:[],max:[],resolution:[]},R=null,b=null,_=[],A=[],H=null;this.domElement=t,this.debug={checkShaderErrors:!0,diagnostics:{keywords:!1},onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this.toneMapping=Ji,this.toneMappingExposure=1,this.transmissionResolutionScale=1;let O=this,T=!1,F=null,B=null,D=null,V=null;this._outputColorSpace=On;let Y=0,$=0,ce=null,P=-1,I=null,q=new Ct,ie=new Ct,he=null,Q=new ct(0),fe=0,le=t.width,me=t.height,pe=1,De=null,Ze=null,Ne=new Ct(0,0,le,me),qe=new Ct(0,0,le,me),ot=!1,Qe=new Os,bt=new Dl,At=!1,sn=!1,Nt=new kt,yn=new W,yt=new Ct,fn={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0},Jt=!1;function rn(){return ce===null?pe:1}let z=n;function Re(E,G){return t.getContext(E,G)}let Je,at,Me,Bt,He,$e,L,S,Z,de,oe,ve,ye,te,se,_e,k,re,ne,we,xe,Se,Ge;try{let E={alpha:!0,depth:s,stencil:r,antialias:a,premultipliedAlpha:c,preserveDrawingBuffer:l,powerPreference:d,failIfMajorPerformanceCaveat:u};if("setAttribute"in t&&t.setAttribute("data-engine",`three.js r${"187"}`),t.addEventListener("webglcontextlost",ke,!1),t.addEventListener("webglcontextrestored",tt,!1),t.addEventListener("webglcontextcreationerror",Ae,!1),z===null){let G="webgl2";if(z=Re(G,E),z===null)throw Re(G)?new Error("THREE.WebGLRenderer: Error creating WebGL context with your selected attributes."):new Error("THREE.WebGLRenderer: Error creating WebGL context.")}et()}catch(E){throw t.removeEventListener("webglcontextlost",ke,!1),t.removeEventListener("webglcontextrestored",tt,!1),t.removeEventListener("webglcontextcreationerror",Ae,!1),it("WebGLRenderer: "+E.message),E}function et(){Je=new Ly(z),Je.init(),xe=new pS(z,Je),at=new by(z,Je,e,xe),Me=new dS(z,Je),at.reversedDepthBuffer&&h&&Me.buffers.depth.setReversed(!0),B=z.createFramebuffer(),D=z.createFramebuffer(),V=z.createFramebuffer(),Bt=new Uy(z),He=new jb,$e=new fS(z,Je,Me,He,at,xe,Bt),L=new Iy(O),S=new O_(z),Se=new vy(z,S),Z=new Dy(z,S,Bt,Se),de=new Oy(z,Z,S,Se,Bt),re=new Fy(z,at,$e),se=new Sy(He),oe=new Kb(O,L,Je,at,Se,se),ve=new xS(O,He),ye=new eS,te=new oS(Je),k=new xy(O,L,Me,de,g,c),_e=new uS(O,de,at),Ge=new vS(z,Bt,at,Me),ne=new yy(z,Je,Bt),we=new Ny(z,Je,Bt),Bt.programs=oe.programs,O.capabilities=at,O.extensions=Je,O.properties=He,O.renderLists=ye,O.shadowMap=_e,O.state=Me,O.info=Bt}v!==Qn&&(H=new ky(v,t.width,t.height,a,s,r));let ue=new nd(O,z);this.xr=ue,this.getContext=function(){return z},this.getContextAttributes=function(){return z.getContextAttributes()},this.forceContextLoss=function(){let E=Je.get("WEBGL_lose_context");E&&E.loseContext()},this.forceContextRestore=function(){let E=Je.get("WEBGL_lose_context");E&&E.restoreContext()},this.getPixelRatio=function(){return pe},this.setPixelRatio=function(E){E!==void 0&&(pe=E,this.setSize(le,me,!1))},this.getSize=function(E){return E.set(le,me)},this.setSize=function(E,G,ee=!0){if(ue.isPresenting){Ye("WebGLRenderer: Can't change size while VR device is presenting.");return}le=E,me=G,t.width=Math.floor(E*pe),t.height=Math.floor(G*pe),ee===!0&&(t.style.width=E+"px",t.style.height=G+"px"),H!==null&&H.setSize(t.width,t.height),this.setViewport(0,0,E,G)},this.getDrawingBufferSize=function(E){return E.set(le*pe,me*pe).floor()},this.setDrawingBufferSize=function(E,G,ee){le=E,me=G,pe=ee,t.width=Math.floor(E*ee),t.height=Math.floor(G*ee),this.setViewport(0,0,E,G)},this.setEffects=function(E){if(v===Qn){it("WebGLRenderer: setEffects() requires outputBufferType set to HalfFloatType or FloatType.");return}if(E){for(let G=0;G<E.length;G++)if(E[G].isOutputPass===!0){Ye("WebGLRenderer: OutputPass is not needed in setEffects(). Tone mapping and color space conversion are applied automatically.");break}}H.setEffects(E||[])},this.getCurrentViewport=function(E){return E.copy(q)},this.getViewport=function(E){return E.copy(Ne)},this.setViewport=function(E,G,ee,J){E.isVector4?Ne.set(E.x,E.y,E.z,E.w):Ne.set(E,G,ee,J),Me.viewport(q.copy(Ne).multiplyScalar(rn()).round())},this.getScissor=function(E){return E.copy(qe)},this.setScissor=function(E,G,ee,J){E.isVector4?qe.set(E.x,E.y,E.z,E.w):qe.set(E,G,ee,J),Me.scissor(ie.copy(qe).multiplyScalar(rn()).round())},this.getScissorTest=function(){return ot},this.setScissorTest=function(E){Me.setScissorTest(ot=E)},this.setOpaqueSort=function(E){De=E},this.setTransparentSort=function(E){Ze=E},this.getClearColor=function(E){return E.copy(k.getClearColor())},this.setClearColor=function(){k.setClearColor(...arguments)},this.getClearAlpha=function(){return k.getClearAlpha()},this.setClearAlpha=function(){k.setClearAlpha(...arguments)},this.clear=function(E=!0,G=!0,ee=!0){let J=0;if(E){let K=!1;if(ce!==null){let Ee=ce.texture.format;K=p.has(Ee)}if(K){let Ee=ce.texture.type,Pe=f.has(Ee),Te=k.getClearColor(),Ie=k.getClearAlpha(),Ve=Te.r,nt=Te.g,ft=Te.b;Pe?(y[0]=Ve,y[1]=nt,y[2]=ft,y[3]=Ie,z.clearBufferuiv(z.COLOR,0,y)):(C[0]=Ve,C[1]=nt,C[2]=ft,C[3]=Ie,z.clearBufferiv(z.COLOR,0,C))}else J|=z.COLOR_BUFFER_BIT}G&&(J|=z.DEPTH_BUFFER_BIT,this.state.buffers.depth.setMask(!0)),ee&&(J|=z.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),J!==0&&z.clear(J)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.setNodesHandler=function(E){E.setRenderer(this),F=E},this.dispose=function(){t.removeEventListener("webglcontextlost",ke,!1),t.removeEventListener("webglcontextrestored",tt,!1),t.removeEventListener("webglcontextcreationerror",Ae,!1),k.dispose(),ye.dispose(),te.dispose(),$e.dispose(),He.dispose(),L.dispose(),de.dispose(),Z.dispose(),Se.dispose(),Ge.dispose(),oe.dispose(),ue.dispose(),ue.removeEventListener("sessionstart",Ha),ue.removeEventListener("sessionend",ki),ss.stop()};function ke(E){E.preventDefault(),Yo("WebGLRenderer: Context Lost."),T=!0}function tt(){Yo("WebGLRenderer: Context Restored."),T=!1;let E=Bt.autoReset,G=_e.enabled,ee=_e.autoUpdate,J=_e.needsUpdate,K=_e.type;et(),Bt.autoReset=E,_e.enabled=G,_e.autoUpdate=ee,_e.needsUpdate=J,_e.type=K}function Ae(E){it("WebGLRenderer: A WebGL context could not be created. Reason: ",E.statusMessage)}function ht(E){let G=E.target;G.removeEventListener("dispose",ht),Ht(G)}function Ht(E){kn(E),He.remove(E)}function kn(E){let G=He.get(E).programs;G!==void 0&&(G.forEach(function(ee){oe.releaseProgram(ee)}),E.isShaderMaterial&&oe.releaseShaderCache(E))}this.renderBufferDirect=function(E,G,ee,J,K,Ee){G===null&&(G=fn);let Pe=K.isMesh&&K.matrixWorld.determinantAffine()<0,Te=Po(E,G,ee,J,K);Me.setMaterial(J,Pe);let Ie=ee.index,Ve=1;if(J.wireframe===!0){if(Ie=Z.getWireframeAttribute(ee),Ie===void 0)return;Ve=2}let nt=ee.drawRange,ft=ee.attributes.position,ze=nt.start*Ve,pt=(nt.start+nt.count)*Ve;Ee!==null&&(ze=Math.max(ze,Ee.start*Ve),pt=Math.min(pt,(Ee.start+Ee.count)*Ve)),Ie!==null?(ze=Math.max(ze,0),pt=Math.min(pt,Ie.count)):ft!=null&&(ze=Math.max(ze,0),pt=Math.min(pt,ft.count));let Zt=pt-ze;if(Zt<0||Zt===1/0)return;Se.setup(K,J,Te,ee,Ie);let It,Lt=ne;if(Ie!==null&&(It=S.get(Ie),Lt=we,Lt.setIndex(It)),K.isMesh)J.wireframe===!0?(Me.setLineWidth(J.wireframeLinewidth*rn()),Lt.setMode(z.LINES)):Lt.setMode(z.TRIANGLES);else if(K.isLine){let pn=J.linewidth;pn===void 0&&(pn=1),Me.setLineWidth(pn*rn()),K.isLineSegments?Lt.setMode(z.LINES):K.isLineLoop?Lt.setMode(z.LINE_LOOP):Lt.setMode(z.LINE_STRIP)}else K.isPoints?Lt.setMode(z.POINTS):K.isSprite&&Lt.setMode(z.TRIANGLES);if(K.isBatchedMesh)if(Je.get("WEBGL_multi_draw"))Lt.renderMultiDraw(K._multiDrawStarts,K._multiDrawCounts,K._multiDrawCount);else{let pn=K._multiDrawStarts,Oe=K._multiDrawCounts,on=K._multiDrawCount,gt=Ie?S.get(Ie).bytesPerElement:1,os=He.get(J).currentProgram.getUniforms();for(let an=0;an<on;an++)os.setValue(z,"_gl_DrawID",an),Lt.render(pn[an]/gt,Oe[an])}else if(K.isInstancedMesh)Lt.renderInstances(ze,Zt,K.count);else if(ee.isInstancedBufferGeometry){let pn=ee._maxInstanceCount!==void 0?ee._maxInstanceCount:1/0,Oe=Math.min(ee.instanceCount,pn);Lt.renderInstances(ze,Zt,Oe)}else Lt.render(ze,Zt)};function Ao(E,G,ee,J){F!==null&&E.isNodeMaterial&&F.setObject(J,E),At===!0&&se.setState(E,ee,!1),E.transparent===!0&&E.side===Zi&&E.forceSinglePass===!1?(E.side=Yn,E.needsUpdate=!0,zi(E,G,J),E.side=Ws,E.needsUpdate=!0,zi(E,G,J),E.side=Zi):zi(E,G,J)}this.compile=function(E,G,ee=null){ee===null&&(ee=E),F!==null&&F.renderStart(E,G,ee),b=te.get(ee),b.init(G),A.push(b),ee.traverseVisible(function(K){K.isLight&&K.layers.test(G.layers)&&(b.pushLight(K),K.castShadow&&b.pushShadow(K))}),E!==ee&&E.traverseVisible(function(K){K.isLight&&K.layers.test(G.layers)&&(b.pushLight(K),K.castShadow&&b.pushShadow(K))}),b.setupLights(),F!==null&&F.updateLights(b.state.lightsArray),sn=this.localClippingEnabled,At=se.init(this.clippingPlanes,sn),At===!0&&se.setGlobalState(this.clippingPlanes,G),F!==null&&_e.render(b.state.shadowsArray,ee,G);let J=new Set;return E.traverse(function(K){if(!(K.isMesh||K.isPoints||K.isLine||K.isSprite))return;let Ee=K.material;if(Ee)if(Array.isArray(Ee))for(let Pe=0;Pe<Ee.length;Pe++){let Te=Ee[Pe];Ao(Te,ee,G,K),J.add(Te)}else Ao(Ee,ee,G,K),J.add(Ee)}),b=A.pop(),F!==null&&F.renderEnd(),J},this.compileAsync=function(E,G,ee=null){let J=this.compile(E,G,ee);return new Promise(K=>{function Ee(){if(J.forEach(function(Pe){let Ie=He.get(Pe).currentProgram;(Ie===void 0||Ie.isReady())&&J.delete(Pe)}),J.size===0){K(E);return}setTimeout(Ee,10)}Je.get("KHR_parallel_shader_compile")!==null?Ee():setTimeout(Ee,10)})};let xr=null;function Sh(E){xr&&xr(E)}function Ha(){ss.stop()}function ki(){ss.start()}let ss=new nm;ss.setAnimationLoop(Sh),typeof self<"u"&&ss.setContext(self),this.setAnimationLoop=function(E){xr=E,ue.setAnimationLoop(E),E===null?ss.stop():ss.start()},ue.addEventListener("sessionstart",Ha),ue.addEventListener("sessionend",ki),this.render=function(E,G){if(G!==void 0&&G.isCamera!==!0){it("WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(T===!0)return;F!==null&&F.renderStart(E,G);let ee=ue.enabled===!0&&ue.isPresenting===!0,J=H!==null&&(ce===null||ee)&&H.begin(O,ce);if(E.matrixWorldAutoUpdate===!0&&E.updateMatrixWorld(),G.parent===null&&G.matrixWorldAutoUpdate===!0&&G.updateMatrixWorld(),ue.enabled===!0&&ue.isPresenting===!0&&(H===null||H.isCompositing()===!1)&&(ue.cameraAutoUpdate===!0&&ue.updateCamera(G),G=ue.getCamera()),E.isScene===!0&&E.onBeforeRender(O,E,G,ce),b=te.get(E,A.length),b.init(G),b.state.textureUnits=$e.getTextureUnits(),A.push(b),Nt.multiplyMatrices(G.projectionMatrix,G.matrixWorldInverse),G.isArrayCamera?bt.setFromArrayCamera(G):Qe.setFromProjectionMatrix(Nt,vi,G.reversedDepth),sn=this.localClippingEnabled,At=se.init(this.clippingPlanes,sn),R=ye.get(E,_.length),R.init(),_.push(R),this.info.render.frame++,ue.enabled===!0&&ue.isPresenting===!0){let Pe=O.xr.getDepthSensingMesh();Pe!==null&&rs(Pe,G,-1/0,O.sortObjects)}rs(E,G,0,O.sortObjects),R.finish(),F!==null&&F.updateLights(b.state.lightsArray),O.sortObjects===!0&&R.sort(De,Ze),Jt=ue.enabled===!1||ue.isPresenting===!1||ue.hasDepthSensing()===!1,Jt&&k.addToRenderList(R,E),this.info.autoReset===!0&&this.info.reset(),At===!0&&se.beginShadows();let K=b.state.shadowsArray;if(_e.render(K,E,G),At===!0&&se.endShadows(),(J&&H.hasRenderPass())===!1){let Pe=R.opaque,Te=R.transmissive;if(b.setupLights(),G.isArrayCamera){let Ie=G.cameras;if(Te.length>0)for(let Ve=0,nt=Ie.length;Ve<nt;Ve++){let ft=Ie[Ve];Mi(Pe,Te,E,ft)}Jt&&k.render(E);for(let Ve=0,nt=Ie.length;Ve<nt;Ve++){let ft=Ie[Ve];Ro(R,E,ft,ft.viewport)}}else Te.length>0&&Mi(Pe,Te,E,G),Jt&&k.render(E),Ro(R,E,G)}ce!==null&&$===0&&($e.updateMultisampleRenderTarget(ce),$e.updateRenderTargetMipmap(ce)),J&&H.end(O),E.isScene===!0&&E.onAfterRender(O,E,G),Se.resetDefaultState(),P=-1,I=null,A.pop(),A.length>0?(b=A[A.length-1],$e.setTextureUnits(b.state.textureUnits),At===!0&&se.setGlobalState(O.clippingPlanes,b.state.camera)):b=null,_.pop(),_.length>0?R=_[_.length-1]:R=null,F!==null&&F.renderEnd()};function rs(E,G,ee,J){if(E.visible===!1)return;if(E.layers.test(G.layers)){if(E.isGroup)ee=E.renderOrder;else if(E.isLOD)E.autoUpdate===!0&&E.update(G);else if(E.isLight)b.pushLight(E),E.castShadow&&b.pushShadow(E);else if(E.isSprite){let Pe=G.isArrayCamera?bt:Qe;if(!E.frustumCulled||E.intersectsFrustum(Pe)){J&&yt.setFromMatrixPosition(E.matrixWorld).applyMatrix4(Nt);let Te=de.update(E),Ie=E.material;Ie.visible&&R.push(E,Te,Ie,ee,yt.z,null,G)}}else if(E.isMesh||E.isLine||E.isPoints){let Pe=G.isArrayCamera?bt:Qe;if(!E.frustumCulled||E.intersectsFrustum(Pe)){let Te=de.update(E),Ie=E.material;if(J&&(E.boundingSphere!==void 0?(E.boundingSphere===null&&E.computeBoundingSphere(),yt.copy(E.boundingSphere.center)):(Te.boundingSphere===null&&Te.computeBoundingSphere(),yt.copy(Te.boundingSphere.center)),yt.applyMatrix4(E.matrixWorld).applyMatrix4(Nt)),Array.isArray(Ie)){let Ve=Te.groups;for(let nt=0,ft=Ve.length;nt<ft;nt++){let ze=Ve[nt],pt=Ie[ze.materialIndex];pt&&pt.visible&&R.push(E,Te,pt,ee,yt.z,ze,G)}}else Ie.visible&&R.push(E,Te,Ie,ee,yt.z,null,G)}}}let Ee=E.children;for(let Pe=0,Te=Ee.length;Pe<Te;Pe++)rs(Ee[Pe],G,ee,J)}function Ro(E,G,ee,J){let{opaque:K,transmissive:Ee,transparent:Pe}=E;b.setupLightsView(ee),At===!0&&se.setGlobalState(O.clippingPlanes,ee),J&&Me.viewport(q.copy(J)),K.length>0&&Kt(K,G,ee),Ee.length>0&&Kt(Ee,G,ee),Pe.length>0&&Kt(Pe,G,ee),Me.buffers.depth.setTest(!0),Me.buffers.depth.setMask(!0),Me.buffers.color.setMask(!0),Me.setPolygonOffset(!1)}function Mi(E,G,ee,J){if((ee.isScene===!0?ee.overrideMaterial:null)!==null)return;if(b.state.transmissionRenderTarget[J.id]===void 0){let ze=Je.has("EXT_color_buffer_half_float")||Je.has("EXT_color_buffer_float");b.state.transmissionRenderTarget[J.id]=new hi(1,1,{generateMipmaps:!0,type:ze?Ni:Qn,minFilter:ys,samples:Math.max(4,at.samples),stencilBuffer:r,resolveDepthBuffer:!1,resolveStencilBuffer:!1,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,colorSpace:_t.workingColorSpace})}let Ee=b.state.transmissionRenderTarget[J.id],Pe=J.viewport||q;Ee.setSize(Pe.z*O.transmissionResolutionScale,Pe.w*O.transmissionResolutionScale);let Te=O.getRenderTarget(),Ie=O.getActiveCubeFace(),Ve=O.getActiveMipmapLevel();O.setRenderTarget(Ee),O.getClearColor(Q),fe=O.getClearAlpha(),fe<1&&O.setClearColor(16777215,.5),O.clear(),Jt&&k.render(ee);let nt=O.toneMapping;O.toneMapping=Ji;let ft=J.viewport;if(J.viewport!==void 0&&(J.viewport=void 0),b.setupLightsView(J),At===!0&&se.setGlobalState(O.clippingPlanes,J),Kt(E,ee,J),$e.updateMultisampleRenderTarget(Ee),$e.updateRenderTargetMipmap(Ee),Je.has("WEBGL_multisampled_render_to_texture")===!1){let ze=!1;for(let pt=0,Zt=G.length;pt<Zt;pt++){let It=G[pt],{object:Lt,geometry:pn,material:Oe,group:on}=It;if(Oe.side===Zi&&Lt.layers.test(J.layers)){let gt=Oe.side;Oe.side=Yn,Oe.needsUpdate=!0,tn(Lt,ee,J,pn,Oe,on),Oe.side=gt,Oe.needsUpdate=!0,ze=!0}}ze===!0&&($e.updateMultisampleRenderTarget(Ee),$e.updateRenderTargetMipmap(Ee))}O.setRenderTarget(Te,Ie,Ve),O.setClearColor(Q,fe),ft!==void 0&&(J.viewport=ft),O.toneMapping=nt}function Kt(E,G,ee){let J=G.isScene===!0?G.overrideMaterial:null;for(let K=0,Ee=E.length;K<Ee;K++){let Pe=E[K],{object:Te,geometry:Ie,group:Ve}=Pe,nt=Pe.material;nt.allowOverride===!0&&J!==null&&(nt=J),Te.layers.test(ee.layers)&&tn(Te,G,ee,Ie,nt,Ve)}}function tn(E,G,ee,J,K,Ee){F!==null&&K.isNodeMaterial&&F.setObject(E,K),E.onBeforeRender(O,G,ee,J,K,Ee),E.modelViewMatrix.multiplyMatrices(ee.matrixWorldInverse,E.matrixWorld),E.normalMatrix.getNormalMatrix(E.modelViewMatrix),K.onBeforeRender(O,G,ee,J,E,Ee),K.transparent===!0&&K.side===Zi&&K.forceSinglePass===!1?(K.side=Yn,K.needsUpdate=!0,O.renderBufferDirect(ee,G,J,K,E,Ee),K.side=Ws,K.needsUpdate=!0,O.renderBufferDirect(ee,G,J,K,E,Ee),K.side=Zi):O.renderBufferDirect(ee,G,J,K,E,Ee),E.onAfterRender(O,G,ee,J,K,Ee)}function nn(E){let G=0;for(let ee of E)ee.texture!==null&&G++;return G}function zi(E,G,ee){G.isScene!==!0&&(G=fn);let J=He.get(E),K=b.state.lights,Ee=b.state.shadowsArray,Pe=K.state.version,Te=oe.getParameters(E,K.state,Ee,G,ee,b.state.lightProbeGridArray),Ie=oe.getProgramCacheKey(Te),Ve=J.programs;J.environment=E.isMeshStandardMaterial||E.isMeshLambertMaterial||E.isMeshPhongMaterial?G.environment:null,J.fog=G.fog;let nt=E.isMeshStandardMaterial||E.isMeshLambertMaterial&&!E.envMap||E.isMeshPhongMaterial&&!E.envMap;J.envMap=L.get(E.envMap||J.environment,nt),J.envMapRotation=J.environment!==null&&E.envMap===null?G.environmentRotation:E.envMapRotation,Ve===void 0&&(E.addEventListener("dispose",ht),Ve=new Map,J.programs=Ve,J.programVariants=new Map);let ft=Ve.get(Ie);if(ft!==void 0){if(J.currentProgram===ft&&J.lightsStateVersion===Pe)return Co(E,Te),ft}else Te.uniforms=oe.getUniforms(E),F!==null&&E.isNodeMaterial&&F.build(E,ee,Te),E.onBeforeCompile(Te,O),ft=oe.acquireProgram(Te,Ie),Ve.set(Ie,ft),J.uniforms=Te.uniforms;let ze=J.uniforms;return(!E.isShaderMaterial&&!E.isRawShaderMaterial||E.clipping===!0)&&(ze.clippingPlanes=se.uniform),Co(E,Te),J.needsLights=Ts(E),J.lightsStateVersion=Pe,J.needsLights&&(ze.ambientLightColor.value=K.state.ambient,ze.lightProbe.value=K.state.probe,ze.sunLights.value=K.state.sun,ze.sunLightShadows.value=K.state.sunShadow,ze.directionalLights.value=K.state.directional,ze.directionalLightShadows.value=K.state.directionalShadow,ze.spotLights.value=K.state.spot,ze.spotLightShadows.value=K.state.spotShadow,ze.rectAreaLights.value=K.state.rectArea,ze.ltc_1.value=K.state.rectAreaLTC1,ze.ltc_2.value=K.state.rectAreaLTC2,ze.pointLights.value=K.state.point,ze.pointLightShadows.value=K.state.pointShadow,ze.hemisphereLights.value=K.state.hemi,ze.sunShadowMatrix.value=K.state.sunShadowMatrix,ze.sunShadowCascade.value=K.state.sunShadowCascade,ze.directionalShadowMatrix.value=K.state.directionalShadowMatrix,ze.spotLightMatrix.value=K.state.spotLightMatrix,ze.spotLightMap.value=K.state.spotLightMap,ze.pointShadowMatrix.value=K.state.pointShadowMatrix),J.numLightProbeGrids=nn(b.state.lightProbeGridArray),J.currentProgram=ft,J.uniformsList=null,ft}function ti(E,G,ee,J,K){let Ee=He.get(E),Pe=Ee.currentProgram.id+","+J+","+K,Te=Ee.programVariants.get(Pe);return Te===void 0?(Te=zi(E,G,ee),Ee.programVariants.set(Pe,Te)):(Ee.currentProgram=Te,Ee.uniformsList=null,Ee.outputColorSpace=J,Ee.toneMapping=K),Te}function Es(E){if(E.uniformsList===null){let G=E.currentProgram.getUniforms();E.uniformsList=oo.seqWithValue(G.seq,E.uniforms)}return E.uniformsList}function Co(E,G){let ee=He.get(E);ee.outputColorSpace=G.outputColorSpace,ee.batching=G.batching,ee.batchingColor=G.batchingColor,ee.instancing=G.instancing,ee.instancingColor=G.instancingColor,ee.instancingMorph=G.instancingMorph,ee.skinning=G.skinning,ee.morphTargets=G.morphTargets,ee.morphNormals=G.morphNormals,ee.morphColors=G.morphColors,ee.morphTargetsCount=G.morphTargetsCount,ee.numClippingPlanes=G.numClippingPlanes,ee.numIntersection=G.numClipIntersection,ee.vertexAlphas=G.vertexAlphas,ee.vertexTangents=G.vertexTangents,ee.toneMapping=G.toneMapping}function Po(E,G,ee,J,K){G.isScene!==!0&&(G=fn),$e.resetTextureUnits();let Ee=G.fog,Pe=J.isMeshStandardMaterial||J.isMeshLambertMaterial||J.isMeshPhongMaterial?G.environment:null,Te=ce===null?O.outputColorSpace:ce.isXRRenderTarget===!0?ce.texture.colorSpace:_t.workingColorSpace,Ie=J.isMeshStandardMaterial||J.isMeshLambertMaterial&&!J.envMap||J.isMeshPhongMaterial&&!J.envMap,Ve=L.get(J.envMap||Pe,Ie),nt=J.vertexColors===!0&&!!ee.attributes.color&&ee.attributes.color.itemSize===4,ft=!!ee.attributes.tangent&&(!!J.normalMap||J.anisotropy>0),ze=!!ee.morphAttributes.position,pt=!!ee.morphAttributes.normal,Zt=!!ee.morphAttributes.color,It=Ji;J.toneMapped&&(ce===null||ce.isXRRenderTarget===!0)&&(It=O.toneMapping);let Lt=ee.morphAttributes.position||ee.morphAttributes.normal||ee.morphAttributes.color,pn=Lt!==void 0?Lt.length:0,Oe=He.get(J),on=b.state.lights;if(At===!0&&(sn===!0||E!==I)){let Dt=E===I&&J.id===P;se.setState(J,E,Dt)}let gt=!1,os=!1;J.version===Oe.__version?Oe.needsLights&&Oe.lightsStateVersion!==on.state.version||K.isBatchedMesh&&Oe.batching===!1||!K.isBatchedMesh&&Oe.batching===!0||K.isBatchedMesh&&Oe.batchingColor===!0&&K._colorsTexture===null||K.isBatchedMesh&&Oe.batchingColor===!1&&K._colorsTexture!==null||K.isInstancedMesh&&Oe.instancing===!1||!K.isInstancedMesh&&Oe.instancing===!0||K.isSkinnedMesh&&Oe.skinning===!1||!K.isSkinnedMesh&&Oe.skinning===!0||K.isInstancedMesh&&Oe.instancingColor===!0&&K.instanceColor===null||K.isInstancedMesh&&Oe.instancingColor===!1&&K.instanceColor!==null||K.isInstancedMesh&&Oe.instancingMorph===!0&&K.morphTexture===null||K.isInstancedMesh&&Oe.instancingMorph===!1&&K.morphTexture!==null||Oe.envMap!==Ve||J.fog===!0&&Oe.fog!==Ee||Oe.numClippingPlanes!==void 0&&(Oe.numClippingPlanes!==se.numPlanes||Oe.numIntersection!==se.numIntersection)||Oe.vertexAlphas!==nt||Oe.vertexTangents!==ft||Oe.morphTargets!==ze||Oe.morphNormals!==pt||Oe.morphColors!==Zt||Oe.morphTargetsCount!==pn||Oe.numLightProbeGrids!==nn(b.state.lightProbeGridArray)?gt=!0:(Oe.outputColorSpace!==Te||Oe.toneMapping!==It)&&(os=!0):(gt=!0,Oe.__version=J.version);let an=Oe.currentProgram;(gt===!0||os===!0)&&(an=os===!0?ti(J,G,K,Te,It):zi(J,G,K),F&&J.isNodeMaterial&&F.onUpdateProgram(J,an,Oe));let br=!1,Vi=!1,as=!1,ut=an.getUniforms(),jt=Oe.uniforms;if(Me.useProgram(an.program)&&(br=!0,Vi=!0,as=!0),J.id!==P&&(P=J.id,Vi=!0),br||I!==E){Me.buffers.depth.getReversed()&&E.reversedDepth!==!0&&(E._reversedDepth=!0,E.updateProjectionMatrix()),ut.setValue(z,"projectionMatrix",E.projectionMatrix),ut.setValue(z,"viewMatrix",E.matrixWorldInverse);let ln=ut.map.cameraPosition;ln!==void 0&&ln.setValue(z,yn.setFromMatrixPosition(E.matrixWorld)),at.logarithmicDepthBuffer&&ut.setValue(z,"logDepthBufFC",2/(Math.log(E.far+1)/Math.LN2)),(J.isMeshPhongMaterial||J.isMeshToonMaterial||J.isMeshLambertMaterial||J.isMeshBasicMaterial||J.isMeshStandardMaterial||J.isShaderMaterial)&&ut.setValue(z,"isOrthographic",E.isOrthographicCamera===!0),I!==E&&(I=E,Vi=!0,as=!0)}if(Oe.needsLights&&(on.state.sunShadowMap.length>0&&ut.setValue(z,"sunShadowMap",on.state.sunShadowMap,$e),on.state.directionalShadowMap.length>0&&ut.setValue(z,"directionalShadowMap",on.state.directionalShadowMap,$e),on.state.spotShadowMap.length>0&&ut.setValue(z,"spotShadowMap",on.state.spotShadowMap,$e),on.state.pointShadowMap.length>0&&ut.setValue(z,"pointShadowMap",on.state.pointShadowMap,$e)),K.isSkinnedMesh){ut.setOptional(z,K,"bindMatrix"),ut.setOptional(z,K,"bindMatrixInverse");let Dt=K.skeleton;Dt&&(Dt.boneTexture===null&&Dt.computeBoneTexture(),ut.setValue(z,"boneTexture",Dt.boneTexture,$e))}K.isBatchedMesh&&(ut.setOptional(z,K,"batchingTexture"),ut.setValue(z,"batchingTexture",K._matricesTexture,$e),ut.setOptional(z,K,"batchingIdTexture"),ut.setValue(z,"batchingIdTexture",K._indirectTexture,$e),ut.setOptional(z,K,"batchingColorTexture"),K._colorsTexture!==null&&ut.setValue(z,"batchingColorTexture",K._colorsTexture,$e));let zn=ee.morphAttributes;if((zn.position!==void 0||zn.normal!==void 0||zn.color!==void 0)&&re.update(K,ee,an),(Vi||Oe.receiveShadow!==K.receiveShadow)&&(Oe.receiveShadow=K.receiveShadow,ut.setValue(z,"receiveShadow",K.receiveShadow)),(J.isMeshStandardMaterial||J.isMeshLambertMaterial||J.isMeshPhongMaterial)&&J.envMap===null&&G.environment!==null&&(jt.envMapIntensity.value=G.environmentIntensity),jt.dfgLUT!==void 0&&(jt.dfgLUT.value=bS()),Vi){if(ut.setValue(z,"toneMappingExposure",O.toneMappingExposure),Oe.needsLights&&vr(jt,as),Ee&&J.fog===!0&&ve.refreshFogUniforms(jt,Ee),ve.refreshMaterialUniforms(jt,J,pe,me,b.state.transmissionRenderTarget[E.id]),Oe.needsLights&&Oe.numLightProbeGrids>0){let Dt=M,ln=0;for(let Nn of b.state.lightProbeGridArray)Nn.texture!==null&&(Dt.textures[ln]=Nn.texture,Dt.min[ln]=Nn.boundingBox.min,Dt.max[ln]=Nn.boundingBox.max,Dt.resolution[ln]=Nn.resolution,ln++);for(let Nn in Dt)Dt[Nn].length=ln;jt.probesSH.value=Dt.textures,jt.probesMin.value=Dt.min,jt.probesMax.value=Dt.max,jt.probesResolution.value=Dt.resolution}oo.upload(z,Es(Oe),jt,$e)}if(J.isShaderMaterial&&J.uniformsNeedUpdate===!0&&(oo.upload(z,Es(Oe),jt,$e),J.uniformsNeedUpdate=!1),J.isSpriteMaterial&&ut.setValue(z,"center",K.center),ut.setValue(z,"modelViewMatrix",K.modelViewMatrix),ut.setValue(z,"normalMatrix",K.normalMatrix),ut.setValue(z,"modelMatrix",K.matrixWorld),J.uniformsGroups!==void 0){let Dt=J.uniformsGroups;for(let ln=0,Nn=Dt.length;ln<Nn;ln++){let Ga=Dt[ln];Ge.update(Ga,an),Ge.bind(Ga,an)}}return an}function vr(E,G){E.ambientLightColor.needsUpdate=G,E.lightProbe.needsUpdate=G,E.sunLights.needsUpdate=G,E.sunLightShadows.needsUpdate=G,E.directionalLights.needsUpdate=G,E.directionalLightShadows.needsUpdate=G,E.pointLights.needsUpdate=G,E.pointLightShadows.needsUpdate=G,E.spotLights.needsUpdate=G,E.spotLightShadows.needsUpdate=G,E.rectAreaLights.needsUpdate=G,E.hemisphereLights.needsUpdate=G}function Ts(E){return E.isMeshLambertMaterial||E.isMeshToonMaterial||E.isMeshPhongMaterial||E.isMeshStandardMaterial||E.isShadowMaterial||E.isShaderMaterial&&E.lights===!0}this.getActiveCubeFace=function(){return Y},this.getActiveMipmapLevel=function(){return $},this.getRenderTarget=function(){return ce},this.setRenderTargetTextures=function(E,G,ee){let J=He.get(E);J.__autoAllocateDepthBuffer=E.resolveDepthBuffer===!1,J.__autoAllocateDepthBuffer===!1&&(J.__useRenderToTexture=!1),He.get(E.texture).__webglTexture=G,He.get(E.depthTexture).__webglTexture=J.__autoAllocateDepthBuffer?void 0:ee,J.__hasExternalTextures=!0},this.setRenderTargetFramebuffer=function(E,G){let ee=He.get(E);ee.__webglFramebuffer=G,ee.__useDefaultFramebuffer=G===void 0},this.setRenderTarget=function(E,G=0,ee=0){ce=E,Y=G,$=ee;let J=null,K=!1,Ee=!1;if(E){let Te=He.get(E);if(Te.__useDefaultFramebuffer!==void 0){Me.bindFramebuffer(z.FRAMEBUFFER,Te.__webglFramebuffer),q.copy(E.viewport),ie.copy(E.scissor),he=E.scissorTest,Me.viewport(q),Me.scissor(ie),Me.setScissorTest(he),P=-1;return}else if(Te.__webglFramebuffer===void 0)$e.setupRenderTarget(E);else if(Te.__hasExternalTextures)$e.rebindTextures(E,He.get(E.texture).__webglTexture,He.get(E.depthTexture).__webglTexture);else if(E.depthBuffer){let nt=E.depthTexture;if(Te.__boundDepthTexture!==nt){if(nt!==null&&He.has(nt)&&(E.width!==nt.image.width||E.height!==nt.image.height))throw new Error("THREE.WebGLRenderer: Attached DepthTexture is initialized to the incorrect size.");$e.setupDepthRenderbuffer(E)}}let Ie=E.texture;(Ie.isData3DTexture||Ie.isDataArrayTexture||Ie.isCompressedArrayTexture)&&(Ee=!0);let Ve=He.get(E).__webglFramebuffer;E.isWebGLCubeRenderTarget?(Array.isArray(Ve[G])?J=Ve[G][ee]:J=Ve[G],K=!0):E.samples>0&&$e.useMultisampledRTT(E)===!1?J=He.get(E).__webglMultisampledFramebuffer:Array.isArray(Ve)?J=Ve[ee]:J=Ve,q.copy(E.viewport),ie.copy(E.scissor),he=E.scissorTest}else q.copy(Ne).multiplyScalar(pe).floor(),ie.copy(qe).multiplyScalar(pe).floor(),he=ot;if(ee!==0&&(J=B),Me.bindFramebuffer(z.FRAMEBUFFER,J)&&Me.drawBuffers(E,J),Me.viewport(q),Me.scissor(ie),Me.setScissorTest(he),K){let Te=He.get(E.texture);z.framebufferTexture2D(z.FRAMEBUFFER,z.COLOR_ATTACHMENT0,z.TEXTURE_CUBE_MAP_POSITIVE_X+G,Te.__webglTexture,ee)}else if(Ee){let Te=G;for(let Ie=0;Ie<E.textures.length;Ie++){let Ve=He.get(E.textures[Ie]);z.framebufferTextureLayer(z.FRAMEBUFFER,z.COLOR_ATTACHMENT0+Ie,Ve.__webglTexture,ee,Te)}}else if(E!==null&&ee!==0){let Te=He.get(E.texture);z.framebufferTexture2D(z.FRAMEBUFFER,z.COLOR_ATTACHMENT0,z.TEXTURE_2D,Te.__webglTexture,ee)}P=-1};function yr(E){let G=He.get(E);return(G.__readFormat!==E.format||G.__readType!==E.type)&&(G.__readFormat=E.format,G.__readType=E.type,G.__formatReadable=at.textureFormatReadable(E.format),G.__typeReadable=at.textureTypeReadable(E.type)),G}this.readRenderTargetPixels=function(E,G,ee,J,K,Ee,Pe,Te=0){if(!(E&&E.isWebGLRenderTarget)){it("WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let Ie=He.get(E).__webglFramebuffer;if(E.isWebGLCubeRenderTarget&&Pe!==void 0&&(Ie=Ie[Pe],Array.isArray(Ie)&&(Ie=Ie[0])),Ie){Me.bindFramebuffer(z.FRAMEBUFFER,Ie);try{let Ve=E.textures[Te],nt=Ve.format,ft=Ve.type;E.textures.length>1&&z.readBuffer(z.COLOR_ATTACHMENT0+Te);let ze=yr(Ve);if(ze.__formatReadable===!1){it("WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(ze.__typeReadable===!1){it("WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}G>=0&&G<=E.width-J&&ee>=0&&ee<=E.height-K&&z.readPixels(G,ee,J,K,xe.convert(nt),xe.convert(ft),Ee)}finally{let Ve=ce!==null?He.get(ce).__webglFramebuffer:null;Me.bindFramebuffer(z.FRAMEBUFFER,Ve)}}},this.readRenderTargetPixelsAsync=async function(E,G,ee,J,K,Ee,Pe,Te=0){if(!(E&&E.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let Ie=He.get(E).__webglFramebuffer;if(E.isWebGLCubeRenderTarget&&Pe!==void 0&&(Ie=Ie[Pe],Array.isArray(Ie)&&(Ie=Ie[0])),Ie)if(G>=0&&G<=E.width-J&&ee>=0&&ee<=E.height-K){Me.bindFramebuffer(z.FRAMEBUFFER,Ie);let Ve=E.textures[Te],nt=Ve.format,ft=Ve.type;E.textures.length>1&&z.readBuffer(z.COLOR_ATTACHMENT0+Te);let ze=yr(Ve);if(ze.__formatReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(ze.__typeReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");let pt=z.createBuffer();z.bindBuffer(z.PIXEL_PACK_BUFFER,pt),z.bufferData(z.PIXEL_PACK_BUFFER,Ee.byteLength,z.STREAM_READ),z.readPixels(G,ee,J,K,xe.convert(nt),xe.convert(ft),0),z.bindBuffer(z.PIXEL_PACK_BUFFER,null);let Zt=ce!==null?He.get(ce).__webglFramebuffer:null;Me.bindFramebuffer(z.FRAMEBUFFER,Zt);let It=z.fenceSync(z.SYNC_GPU_COMMANDS_COMPLETE,0);return z.flush(),await Pp(z,It,4),z.bindBuffer(z.PIXEL_PACK_BUFFER,pt),z.getBufferSubData(z.PIXEL_PACK_BUFFER,0,Ee),z.bindBuffer(z.PIXEL_PACK_BUFFER,null),z.deleteBuffer(pt),z.deleteSync(It),Ee}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")},this.copyFramebufferToTexture=function(E,G=null,ee=0){let J=Math.pow(2,-ee),K=Math.floor(E.image.width*J),Ee=Math.floor(E.image.height*J),Pe=G!==null?G.x:0,Te=G!==null?G.y:0;$e.setTexture2D(E,0),z.copyTexSubImage2D(z.TEXTURE_2D,ee,0,0,Pe,Te,K,Ee),Me.unbindTexture()},this.copyTextureToTexture=function(E,G,ee=null,J=null,K=0,Ee=0){let Pe,Te,Ie,Ve,nt,ft,ze,pt,Zt,It=E.isCompressedTexture?E.mipmaps[Ee]:E.image;if(ee!==null)Pe=ee.max.x-ee.min.x,Te=ee.max.y-ee.min.y,Ie=ee.isBox3?ee.max.z-ee.min.z:1,Ve=ee.min.x,nt=ee.min.y,ft=ee.isBox3?ee.min.z:0;else{let ut=Math.pow(2,-K);Pe=Math.floor(It.width*ut),Te=Math.floor(It.height*ut),E.isDataArrayTexture?Ie=It.depth:E.isData3DTexture?Ie=Math.floor(It.depth*ut):Ie=1,Ve=0,nt=0,ft=0}J!==null?(ze=J.x,pt=J.y,Zt=J.z):(ze=0,pt=0,Zt=0);let Lt=xe.convert(G.format),pn=xe.convert(G.type),Oe;G.isData3DTexture?($e.setTexture3D(G,0),Oe=z.TEXTURE_3D):G.isDataArrayTexture||G.isCompressedArrayTexture?($e.setTexture2DArray(G,0),Oe=z.TEXTURE_2D_ARRAY):($e.setTexture2D(G,0),Oe=z.TEXTURE_2D),Me.activeTexture(z.TEXTURE0),Me.pixelStorei(z.UNPACK_FLIP_Y_WEBGL,G.flipY),Me.pixelStorei(z.UNPACK_PREMULTIPLY_ALPHA_WEBGL,G.premultiplyAlpha),Me.pixelStorei(z.UNPACK_ALIGNMENT,G.unpackAlignment);let on=Me.getParameter(z.UNPACK_ROW_LENGTH),gt=Me.getParameter(z.UNPACK_IMAGE_HEIGHT),os=Me.getParameter(z.UNPACK_SKIP_PIXELS),an=Me.getParameter(z.UNPACK_SKIP_ROWS),br=Me.getParameter(z.UNPACK_SKIP_IMAGES);Me.pixelStorei(z.UNPACK_ROW_LENGTH,It.width),Me.pixelStorei(z.UNPACK_IMAGE_HEIGHT,It.height),Me.pixelStorei(z.UNPACK_SKIP_PIXELS,Ve),Me.pixelStorei(z.UNPACK_SKIP_ROWS,nt),Me.pixelStorei(z.UNPACK_SKIP_IMAGES,ft);let Vi=E.isDataArrayTexture||E.isData3DTexture,as=G.isDataArrayTexture||G.isData3DTexture;if(E.isDepthTexture){let ut=He.get(E),jt=He.get(G),zn=He.get(ut.__renderTarget),Dt=He.get(jt.__renderTarget);Me.bindFramebuffer(z.READ_FRAMEBUFFER,zn.__webglFramebuffer),Me.bindFramebuffer(z.DRAW_FRAMEBUFFER,Dt.__webglFramebuffer);for(let ln=0;ln<Ie;ln++)Vi&&(z.framebufferTextureLayer(z.READ_FRAMEBUFFER,z.COLOR_ATTACHMENT0,He.get(E).__webglTexture,K,ft+ln),z.framebufferTextureLayer(z.DRAW_FRAMEBUFFER,z.COLOR_ATTACHMENT0,He.get(G).__webglTexture,Ee,Zt+ln)),z.blitFramebuffer(Ve,nt,Ve+Pe,nt+Te,ze,pt,ze+Pe,pt+Te,z.DEPTH_BUFFER_BIT,z.NEAREST);Me.bindFramebuffer(z.READ_FRAMEBUFFER,null),Me.bindFramebuffer(z.DRAW_FRAMEBUFFER,null)}else if(K!==0||E.isRenderTargetTexture||He.has(E)){let ut=He.get(E),jt=He.get(G);Me.bindFramebuffer(z.READ_FRAMEBUFFER,D),Me.bindFramebuffer(z.DRAW_FRAMEBUFFER,V);for(let zn=0;zn<Ie;zn++)Vi?z.framebufferTextureLayer(z.READ_FRAMEBUFFER,z.COLOR_ATTACHMENT0,ut.__webglTexture,K,ft+zn):z.framebufferTexture2D(z.READ_FRAMEBUFFER,z.COLOR_ATTACHMENT0,z.TEXTURE_2D,ut.__webglTexture,K),as?z.framebufferTextureLayer(z.DRAW_FRAMEBUFFER,z.COLOR_ATTACHMENT0,jt.__webglTexture,Ee,Zt+zn):z.framebufferTexture2D(z.DRAW_FRAMEBUFFER,z.COLOR_ATTACHMENT0,z.TEXTURE_2D,jt.__webglTexture,Ee),K!==0?z.blitFramebuffer(Ve,nt,Ve+Pe,nt+Te,ze,pt,ze+Pe,pt+Te,z.COLOR_BUFFER_BIT,z.NEAREST):as?z.copyTexSubImage3D(Oe,Ee,ze,pt,Zt+zn,Ve,nt,Pe,Te):z.copyTexSubImage2D(Oe,Ee,ze,pt,Ve,nt,Pe,Te);Me.bindFramebuffer(z.READ_FRAMEBUFFER,null),Me.bindFramebuffer(z.DRAW_FRAMEBUFFER,null)}else as?E.isDataTexture||E.isData3DTexture?z.texSubImage3D(Oe,Ee,ze,pt,Zt,Pe,Te,Ie,Lt,pn,It.data):G.isCompressedArrayTexture?z.compressedTexSubImage3D(Oe,Ee,ze,pt,Zt,Pe,Te,Ie,Lt,It.data):z.texSubImage3D(Oe,Ee,ze,pt,Zt,Pe,Te,Ie,Lt,pn,It):E.isDataTexture?z.texSubImage2D(z.TEXTURE_2D,Ee,ze,pt,Pe,Te,Lt,pn,It.data):E.isCompressedTexture?z.compressedTexSubImage2D(z.TEXTURE_2D,Ee,ze,pt,It.width,It.height,Lt,It.data):z.texSubImage2D(z.TEXTURE_2D,Ee,ze,pt,Pe,Te,Lt,pn,It);Me.pixelStorei(z.UNPACK_ROW_LENGTH,on),Me.pixelStorei(z.UNPACK_IMAGE_HEIGHT,gt),Me.pixelStorei(z.UNPACK_SKIP_PIXELS,os),Me.pixelStorei(z.UNPACK_SKIP_ROWS,an),Me.pixelStorei(z.UNPACK_SKIP_IMAGES,br),Ee===0&&G.generateMipmaps===!0&&G.mipmapsAutoUpdate===!0&&z.generateMipmap(Oe),Me.unbindTexture()},this.initRenderTarget=function(E){He.get(E).__webglFramebuffer===void 0&&$e.setupRenderTarget(E)},this.initTexture=function(E){E.isCubeTexture?$e.setTextureCube(E,0):E.isData3DTexture?$e.setTexture3D(E,0):E.isDataArrayTexture||E.isCompressedArrayTexture?$e.setTexture2DArray(E,0):$e.setTexture2D(E,0),Me.unbindTexture()},this.resetState=function(){Y=0,$=0,ce=null,Me.reset(),Se.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return vi}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(e){this._outputColorSpace=e;let t=this.getContext();t.drawingBufferColorSpace=_t._getDrawingBufferColorSpace(e),t.unpackColorSpace=_t._getUnpackColorSpace()}};var fm={type:"change"},sd={type:"start"},mm={type:"end"},$c=new ir,pm=new li,MS=Math.cos(70*Aa.DEG2RAD),_n=new W,ei=2*Math.PI,Et={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},id=1e-6,Xc=class extends xa{constructor(e,t=null){super(e,t),this.state=Et.NONE,this.target=new W,this.cursor=new W,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.keyRotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:Hs.ROTATE,MIDDLE:Hs.DOLLY,RIGHT:Hs.PAN},this.touches={ONE:Gs.ROTATE,TWO:Gs.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._cursorStyle="auto",this._domElementKeyEvents=null,this._lastPosition=new W,this._lastQuaternion=new ci,this._lastTargetPosition=new W,this._quat=new ci().setFromUnitVectors(e.up,new W(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new to,this._sphericalDelta=new to,this._scale=1,this._panOffset=new W,this._rotateStart=new je,this._rotateEnd=new je,this._rotateDelta=new je,this._panStart=new je,this._panEnd=new je,this._panDelta=new je,this._dollyStart=new je,this._dollyEnd=new je,this._dollyDelta=new je,this._dollyDirection=new W,this._mouse=new je,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=ES.bind(this),this._onPointerDown=wS.bind(this),this._onPointerUp=TS.bind(this),this._onContextMenu=DS.bind(this),this._onMouseWheel=CS.bind(this),this._onKeyDown=PS.bind(this),this._onTouchStart=IS.bind(this),this._onTouchMove=LS.bind(this),this._onMouseDown=AS.bind(this),this._onMouseMove=RS.bind(this),this._interceptControlDown=NS.bind(this),this._interceptControlUp=US.bind(this),this.domElement!==null&&this.connect(this.domElement),this.update()}set cursorStyle(e){this._cursorStyle=e,e==="grab"?this.domElement.style.cursor="grab":this.domElement.style.cursor="auto"}get cursorStyle(){return this._cursorStyle}connect(e){super.connect(e),this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.ownerDocument.addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.state=Et.NONE,this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.ownerDocument.removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{capture:!0}),this._controlActive=!1,this._pointers.length=0,this._pointerPositions={},this.domElement.style.touchAction="",this.domElement.style.cursor="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(e){e.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=e}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(fm),this.update(),this.state=Et.NONE}pan(e,t){this._pan(e,t),this.update()}dollyIn(e){this._dollyIn(e),this.update()}dollyOut(e){this._dollyOut(e),this.update()}rotateLeft(e){this._rotateLeft(e),this.update()}rotateUp(e){this._rotateUp(e),this.update()}update(e=null){let t=this.object.position;_n.copy(t).sub(this.target),_n.applyQuaternion(this._quat),this._spherical.setFromVector3(_n),this.autoRotate&&this.state===Et.NONE&&this._rotateLeft(this._getAutoRotationAngle(e)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let n=this.minAzimuthAngle,s=this.maxAzimuthAngle;isFinite(n)&&isFinite(s)&&(n<-Math.PI?n+=ei:n>Math.PI&&(n-=ei),s<-Math.PI?s+=ei:s>Math.PI&&(s-=ei),n<=s?this._spherical.theta=Math.max(n,Math.min(s,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(n+s)/2?Math.max(n,this._spherical.theta):Math.min(s,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let r=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{let o=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),r=o!=this._spherical.radius}if(_n.setFromSpherical(this._spherical),_n.applyQuaternion(this._quatInverse),t.copy(this.target).add(_n),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let o=null;if(this.object.isPerspectiveCamera){let a=_n.length();o=this._clampDistance(a*this._scale);let c=a-o;this.object.position.addScaledVector(this._dollyDirection,c),this.object.updateMatrixWorld(),r=!!c}else if(this.object.isOrthographicCamera){let a=new W(this._mouse.x,this._mouse.y,0);a.unproject(this.object);let c=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),r=c!==this.object.zoom;let l=new W(this._mouse.x,this._mouse.y,0);l.unproject(this.object),this.object.position.sub(l).add(a),this.object.updateMatrixWorld(),o=_n.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;o!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(o).add(this.object.position):($c.origin.copy(this.object.position),$c.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot($c.direction))<MS?this.object.lookAt(this.target):(pm.setFromNormalAndCoplanarPoint(this.object.up,this.target),$c.intersectPlane(pm,this.target))))}else if(this.object.isOrthographicCamera){let o=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),o!==this.object.zoom&&(this.object.updateProjectionMatrix(),r=!0)}return this._scale=1,this._performCursorZoom=!1,r||this._lastPosition.distanceToSquared(this.object.position)>id||8*(1-this._lastQuaternion.dot(this.object.quaternion))>id||this._lastTargetPosition.distanceToSquared(this.target)>id?(this.dispatchEvent(fm),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(e){return e!==null?ei/60*this.autoRotateSpeed*e:ei/60/60*this.autoRotateSpeed}_getZoomScale(e){let t=Math.abs(e*.01);return Math.pow(.95,this.zoomSpeed*t)}_rotateLeft(e){this._sphericalDelta.theta-=e}_rotateUp(e){this._sphericalDelta.phi-=e}_panLeft(e,t){_n.setFromMatrixColumn(t,0),_n.multiplyScalar(-e),this._panOffset.add(_n)}_panUp(e,t){this.screenSpacePanning===!0?_n.setFromMatrixColumn(t,1):(_n.setFromMatrixColumn(t,0),_n.crossVectors(this.object.up,_n)),_n.multiplyScalar(e),this._panOffset.add(_n)}_pan(e,t){let n=this.domElement;if(this.object.isPerspectiveCamera){let s=this.object.position;_n.copy(s).sub(this.target);let r=_n.length();r*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*e*r/n.clientHeight,this.object.matrix),this._panUp(2*t*r/n.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(e*(this.object.right-this.object.left)/this.object.zoom/n.clientWidth,this.object.matrix),this._panUp(t*(this.object.top-this.object.bottom)/this.object.zoom/n.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(e,t){if(!this.zoomToCursor)return;this._performCursorZoom=!0;let n=this.domElement.getBoundingClientRect(),s=e-n.left,r=t-n.top,o=n.width,a=n.height;this._mouse.x=s/o*2-1,this._mouse.y=-(r/a)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(e){return Math.max(this.minDistance,Math.min(this.maxDistance,e))}_handleMouseDownRotate(e){this._rotateStart.set(e.clientX,e.clientY)}_handleMouseDownDolly(e){this._updateZoomParameters(e.clientX,e.clientY),this._dollyStart.set(e.clientX,e.clientY)}_handleMouseDownPan(e){this._panStart.set(e.clientX,e.clientY)}_handleMouseMoveRotate(e){this._rotateEnd.set(e.clientX,e.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let t=this.domElement;this._rotateLeft(ei*this._rotateDelta.x/t.clientHeight),this._rotateUp(ei*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(e){this._dollyEnd.set(e.clientX,e.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.zoomToCursor&&(this._performCursorZoom=!0,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()),this.update()}_handleMouseMovePan(e){this._panEnd.set(e.clientX,e.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(e){this._updateZoomParameters(e.clientX,e.clientY),e.deltaY<0?this._dollyIn(this._getZoomScale(e.deltaY)):e.deltaY>0&&this._dollyOut(this._getZoomScale(e.deltaY)),this.update()}_handleKeyDown(e){let t=!1;switch(e.code){case this.keys.UP:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(ei*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,this.keyPanSpeed),t=!0;break;case this.keys.BOTTOM:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(-ei*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,-this.keyPanSpeed),t=!0;break;case this.keys.LEFT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(ei*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(this.keyPanSpeed,0),t=!0;break;case this.keys.RIGHT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(-ei*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(-this.keyPanSpeed,0),t=!0;break}t&&(e.preventDefault(),this.update())}_handleTouchStartRotate(e){if(this._pointers.length===1)this._rotateStart.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),n=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._rotateStart.set(n,s)}}_handleTouchStartPan(e){if(this._pointers.length===1)this._panStart.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),n=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panStart.set(n,s)}}_handleTouchStartDolly(e){let t=this._getSecondPointerPosition(e),n=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(n*n+s*s);this._dollyStart.set(0,r)}_handleTouchStartDollyPan(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enablePan&&this._handleTouchStartPan(e)}_handleTouchStartDollyRotate(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enableRotate&&this._handleTouchStartRotate(e)}_handleTouchMoveRotate(e){if(this._pointers.length==1)this._rotateEnd.set(e.pageX,e.pageY);else{let n=this._getSecondPointerPosition(e),s=.5*(e.pageX+n.x),r=.5*(e.pageY+n.y);this._rotateEnd.set(s,r)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let t=this.domElement;this._rotateLeft(ei*this._rotateDelta.x/t.clientHeight),this._rotateUp(ei*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(e){if(this._pointers.length===1)this._panEnd.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),n=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panEnd.set(n,s)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(e){let t=this._getSecondPointerPosition(e),n=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(n*n+s*s);this._dollyEnd.set(0,r),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);let o=(e.pageX+t.x)*.5,a=(e.pageY+t.y)*.5;this._updateZoomParameters(o,a)}_handleTouchMoveDollyPan(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enablePan&&this._handleTouchMovePan(e)}_handleTouchMoveDollyRotate(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enableRotate&&this._handleTouchMoveRotate(e)}_addPointer(e){this._pointers.push(e.pointerId)}_removePointer(e){delete this._pointerPositions[e.pointerId];for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId){this._pointers.splice(t,1);return}}_isTrackingPointer(e){for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId)return!0;return!1}_trackPointer(e){let t=this._pointerPositions[e.pointerId];t===void 0&&(t=new je,this._pointerPositions[e.pointerId]=t),t.set(e.pageX,e.pageY)}_getSecondPointerPosition(e){let t=e.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[t]}_customWheelEvent(e){let t=e.deltaMode,n={clientX:e.clientX,clientY:e.clientY,deltaY:e.deltaY};switch(t){case 1:n.deltaY*=16;break;case 2:n.deltaY*=100;break}return e.ctrlKey&&!this._controlActive&&(n.deltaY*=10),n}};function wS(i){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(i.pointerId),this.domElement.ownerDocument.addEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(i)&&(this._addPointer(i),i.pointerType==="touch"?this._onTouchStart(i):this._onMouseDown(i),this._cursorStyle==="grab"&&(this.domElement.style.cursor="grabbing")))}function ES(i){this.enabled!==!1&&(i.pointerType==="touch"?this._onTouchMove(i):this._onMouseMove(i))}function TS(i){switch(this._removePointer(i),this._pointers.length){case 0:this.domElement.releasePointerCapture(i.pointerId),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(mm),this.state=Et.NONE,this._cursorStyle==="grab"&&(this.domElement.style.cursor="grab");break;case 1:let e=this._pointers[0],t=this._pointerPositions[e];this._onTouchStart({pointerId:e,pageX:t.x,pageY:t.y});break}}function AS(i){let e;switch(i.button){case 0:e=this.mouseButtons.LEFT;break;case 1:e=this.mouseButtons.MIDDLE;break;case 2:e=this.mouseButtons.RIGHT;break;default:e=-1}switch(e){case Hs.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(i),this.state=Et.DOLLY;break;case Hs.ROTATE:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=Et.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=Et.ROTATE}break;case Hs.PAN:if(i.ctrlKey||i.metaKey||i.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(i),this.state=Et.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(i),this.state=Et.PAN}break;default:this.state=Et.NONE}this.state!==Et.NONE&&this.dispatchEvent(sd)}function RS(i){switch(this.state){case Et.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(i);break;case Et.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(i);break;case Et.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(i);break}}function CS(i){this.enabled===!1||this.enableZoom===!1||this.state!==Et.NONE||(i.preventDefault(),this.dispatchEvent(sd),this._handleMouseWheel(this._customWheelEvent(i)),this.dispatchEvent(mm))}function PS(i){this.enabled!==!1&&this._handleKeyDown(i)}function IS(i){switch(this._trackPointer(i),this._pointers.length){case 1:switch(this.touches.ONE){case Gs.ROTATE:if(this.enableRotate===!1){this.state=Et.NONE;break}this._handleTouchStartRotate(i),this.state=Et.TOUCH_ROTATE;break;case Gs.PAN:if(this.enablePan===!1){this.state=Et.NONE;break}this._handleTouchStartPan(i),this.state=Et.TOUCH_PAN;break;default:this.state=Et.NONE}break;case 2:switch(this.touches.TWO){case Gs.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(i),this.state=Et.TOUCH_DOLLY_PAN;break;case Gs.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(i),this.state=Et.TOUCH_DOLLY_ROTATE;break;default:this.state=Et.NONE}break;default:this.state=Et.NONE}this.state!==Et.NONE&&this.dispatchEvent(sd)}function LS(i){switch(this._trackPointer(i),this.state){case Et.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(i),this.update();break;case Et.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(i),this.update();break;case Et.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(i),this.update();break;case Et.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(i),this.update();break;default:this.state=Et.NONE}}function DS(i){this.enabled!==!1&&i.preventDefault()}function NS(i){i.key==="Control"&&(this._controlActive=!0,this.domElement.ownerDocument.addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function US(i){i.key==="Control"&&(this._controlActive=!1,this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}var gm=new qn,qc=new W,lo=class extends pa{constructor(){super(),this.isLineSegmentsGeometry=!0,this.type="LineSegmentsGeometry";let e=[-1,2,0,1,2,0,-1,1,0,1,1,0,-1,0,0,1,0,0,-1,-1,0,1,-1,0],t=[-1,2,1,2,-1,1,1,1,-1,-1,1,-1,-1,-2,1,-2],n=[0,2,1,2,3,1,2,4,3,4,5,3,4,6,5,6,7,5];this.setIndex(n),this.setAttribute("position",new Ot(e,3)),this.setAttribute("uv",new Ot(t,2))}applyMatrix4(e){let t=this.attributes.instanceStart,n=this.attributes.instanceEnd;return t!==void 0&&(t.applyMatrix4(e),n.applyMatrix4(e),t.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this}setPositions(e){let t;e instanceof Float32Array?t=e:Array.isArray(e)&&(t=new Float32Array(e));let n=new Vs(t,6,1);return this.setAttribute("instanceStart",new Ii(n,3,0)),this.setAttribute("instanceEnd",new Ii(n,3,3)),this.instanceCount=this.attributes.instanceStart.count,this.computeBoundingBox(),this.computeBoundingSphere(),this}setColors(e){let t;e instanceof Float32Array?t=e:Array.isArray(e)&&(t=new Float32Array(e));let n=new Vs(t,6,1);return this.setAttribute("instanceColorStart",new Ii(n,3,0)),this.setAttribute("instanceColorEnd",new Ii(n,3,3)),this}fromWireframeGeometry(e){return this.setPositions(e.attributes.position.array),this}fromEdgesGeometry(e){return this.setPositions(e.attributes.position.array),this}fromMesh(e){return this.fromWireframeGeometry(new aa(e.geometry)),this}fromLineSegments(e){let t=e.geometry;return this.setPositions(t.attributes.position.array),this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new qn);let e=this.attributes.instanceStart,t=this.attributes.instanceEnd;e!==void 0&&t!==void 0&&(this.boundingBox.setFromBufferAttribute(e),gm.setFromBufferAttribute(t),this.boundingBox.union(gm))}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new Pi),this.boundingBox===null&&this.computeBoundingBox();let e=this.attributes.instanceStart,t=this.attributes.instanceEnd;if(e!==void 0&&t!==void 0){let n=this.boundingSphere.center;this.boundingBox.getCenter(n);let s=0;for(let r=0,o=e.count;r<o;r++)qc.fromBufferAttribute(e,r),s=Math.max(s,n.distanceToSquared(qc)),qc.fromBufferAttribute(t,r),s=Math.max(s,n.distanceToSquared(qc));this.boundingSphere.radius=Math.sqrt(s),isNaN(this.boundingSphere.radius)&&console.error("THREE.LineSegmentsGeometry.computeBoundingSphere(): Computed radius is NaN. The instanced position data is likely to have NaN values.",this)}}toJSON(){}};Ce.line={worldUnits:{value:1},linewidth:{value:1},resolution:{value:new je},dashOffset:{value:0},dashScale:{value:1},dashSize:{value:1},gapSize:{value:1}};Zn.line={uniforms:Ra.merge([Ce.common,Ce.fog,Ce.line]),vertexShader:`
		#include <common>
		#include <color_pars_vertex>
		#include <fog_pars_vertex>
		#include <logdepthbuf_pars_vertex>
		#include <clipping_planes_pars_vertex>

		uniform float linewidth;
		uniform vec2 resolution;

		attribute vec3 instanceStart;
		attribute vec3 instanceEnd;

		attribute vec3 instanceColorStart;
		attribute vec3 instanceColorEnd;

		#ifdef WORLD_UNITS

			varying vec4 worldPos;
			varying vec3 worldStart;
			varying vec3 worldEnd;

			#ifdef USE_DASH

				varying vec2 vUv;

			#endif

		#else

			varying vec2 vUv;

		#endif

		#ifdef USE_DASH

			uniform float dashScale;
			attribute float instanceDistanceStart;
			attribute float instanceDistanceEnd;
			varying float vLineDistance;

		#endif

		float trimSegmentAlpha( const in vec4 start, const in vec4 end ) {

			// compute the interpolation factor needed to trim the segment so it terminates
			// between the camera plane and the near plane

			// conservative estimate of the near plane
			float a = projectionMatrix[ 2 ][ 2 ]; // 3nd entry in 3th column
			float b = projectionMatrix[ 3 ][ 2 ]; // 3nd entry in 4th column

			// we need different nearEstimate formula for reversed and default depth buffer
			// a is positive with a reversed depth buffer so it can be used for controlling the code flow
			float nearEstimate = ( a > 0.0 ) ? ( - b / ( a + 1.0 ) ) : ( - 0.5 * b / a );

			return ( nearEstimate - start.z ) / ( end.z - start.z );

		}

		void main() {

			#ifdef USE_COLOR

				vColor.xyz = ( position.y < 0.5 ) ? instanceColorStart : instanceColorEnd;

			#endif

			float aspect = resolution.x / resolution.y;

			// camera space
			vec4 start = modelViewMatrix * vec4( instanceStart, 1.0 );
			vec4 end = modelViewMatrix * vec4( instanceEnd, 1.0 );

			#ifdef USE_DASH

				float lineDistanceStart = dashScale * instanceDistanceStart;
				float lineDistanceEnd = dashScale * instanceDistanceEnd;

			#endif

			#ifdef WORLD_UNITS

				worldStart = start.xyz;
				worldEnd = end.xyz;

			#else

				vUv = uv;

			#endif

			// special case for perspective projection, and segments that terminate either in, or behind, the camera plane
			// clearly the gpu firmware has a way of addressing this issue when projecting into ndc space
			// but we need to perform ndc-space calculations in the shader, so we must address this issue directly
			// perhaps there is a more elegant solution -- WestLangley

			bool perspective = ( projectionMatrix[ 2 ][ 3 ] == - 1.0 ); // 4th entry in the 3rd column

			if ( perspective ) {

				if ( start.z < 0.0 && end.z >= 0.0 ) {

					float alpha = trimSegmentAlpha( start, end );
					end.xyz = mix( start.xyz, end.xyz, alpha );

					#ifdef USE_DASH

						lineDistanceEnd = mix( lineDistanceStart, lineDistanceEnd, alpha );

					#endif

				} else if ( end.z < 0.0 && start.z >= 0.0 ) {

					float alpha = trimSegmentAlpha( end, start );
					start.xyz = mix( end.xyz, start.xyz, alpha );

					#ifdef USE_DASH

						lineDistanceStart = mix( lineDistanceEnd, lineDistanceStart, alpha );

					#endif

				}

			}

			#ifdef USE_DASH

				vLineDistance = ( position.y < 0.5 ) ? lineDistanceStart : lineDistanceEnd;
				vUv = uv;

			#endif

			// clip space
			vec4 clipStart = projectionMatrix * start;
			vec4 clipEnd = projectionMatrix * end;

			// ndc space
			vec3 ndcStart = clipStart.xyz / clipStart.w;
			vec3 ndcEnd = clipEnd.xyz / clipEnd.w;

			// direction
			vec2 dir = ndcEnd.xy - ndcStart.xy;

			// account for clip-space aspect ratio
			dir.x *= aspect;
			dir = normalize( dir );

			#ifdef WORLD_UNITS

				vec3 worldDir = normalize( end.xyz - start.xyz );
				vec3 tmpFwd = perspective ? normalize( mix( start.xyz, end.xyz, 0.5 ) ) : vec3( 0.0, 0.0, - 1.0 );
				vec3 worldUp = normalize( cross( worldDir, tmpFwd ) );
				vec3 worldFwd = cross( worldDir, worldUp );
				worldPos = position.y < 0.5 ? start: end;

				// height offset
				float hw = linewidth * 0.5;
				worldPos.xyz += position.x < 0.0 ? hw * worldUp : - hw * worldUp;

				// don't extend the line if we're rendering dashes because we
				// won't be rendering the endcaps
				#ifndef USE_DASH

					// cap extension
					worldPos.xyz += position.y < 0.5 ? - hw * worldDir : hw * worldDir;

					// add width to the box
					worldPos.xyz += worldFwd * hw;

					// endcaps
					if ( position.y > 1.0 || position.y < 0.0 ) {

						worldPos.xyz -= worldFwd * 2.0 * hw;

					}

				#endif

				// project the worldpos
				vec4 clip = projectionMatrix * worldPos;

				// shift the depth of the projected points so the line
				// segments overlap neatly
				vec3 clipPose = ( position.y < 0.5 ) ? ndcStart : ndcEnd;

				// only shift the depth of vertices in front of the camera (#35137)
				if ( clip.w > 0.0 ) clip.z = clipPose.z * clip.w;

			#else

				vec2 offset = vec2( dir.y, - dir.x );
				// undo aspect ratio adjustment
				dir.x /= aspect;
				offset.x /= aspect;

				// sign flip
				if ( position.x < 0.0 ) offset *= - 1.0;

				// endcaps
				if ( position.y < 0.0 ) {

					offset += - dir;

				} else if ( position.y > 1.0 ) {

					offset += dir;

				}

				// adjust for linewidth
				offset *= linewidth;

				// adjust for clip-space to screen-space conversion // maybe resolution should be based on viewport ...
				offset /= resolution.y;

				// select end
				vec4 clip = ( position.y < 0.5 ) ? clipStart : clipEnd;

				// back to clip space
				offset *= clip.w;

				clip.xy += offset;

			#endif

			gl_Position = clip;

			vec4 mvPosition = ( position.y < 0.5 ) ? start : end; // this is an approximation

			#include <logdepthbuf_vertex>
			#include <clipping_planes_vertex>
			#include <fog_vertex>

		}
		`,fragmentShader:`
		uniform vec3 diffuse;
		uniform float opacity;
		uniform float linewidth;

		#ifdef USE_DASH

			uniform float dashOffset;
			uniform float dashSize;
			uniform float gapSize;

		#endif

		varying float vLineDistance;

		#ifdef WORLD_UNITS

			varying vec4 worldPos;
			varying vec3 worldStart;
			varying vec3 worldEnd;

			#ifdef USE_DASH

				varying vec2 vUv;

			#endif

		#else

			varying vec2 vUv;

		#endif

		#include <common>
		#include <color_pars_fragment>
		#include <fog_pars_fragment>
		#include <logdepthbuf_pars_fragment>
		#include <clipping_planes_pars_fragment>

		vec2 closestLineToLine(vec3 p1, vec3 p2, vec3 p3, vec3 p4) {

			float mua;
			float mub;

			vec3 p13 = p1 - p3;
			vec3 p43 = p4 - p3;

			vec3 p21 = p2 - p1;

			float d1343 = dot( p13, p43 );
			float d4321 = dot( p43, p21 );
			float d1321 = dot( p13, p21 );
			float d4343 = dot( p43, p43 );
			float d2121 = dot( p21, p21 );

			float denom = d2121 * d4343 - d4321 * d4321;

			float numer = d1343 * d4321 - d1321 * d4343;

			mua = numer / denom;
			mua = clamp( mua, 0.0, 1.0 );
			mub = ( d1343 + d4321 * ( mua ) ) / d4343;
			mub = clamp( mub, 0.0, 1.0 );

			return vec2( mua, mub );

		}

		void main() {

			float alpha = opacity;
			vec4 diffuseColor = vec4( diffuse, alpha );

			#include <clipping_planes_fragment>

			#ifdef USE_DASH

				if ( vUv.y < - 1.0 || vUv.y > 1.0 ) discard; // discard endcaps

				if ( mod( vLineDistance + dashOffset, dashSize + gapSize ) > dashSize ) discard; // todo - FIX

			#endif

			#ifdef WORLD_UNITS

				float len;

				if ( isOrthographic ) {

					// View rays are parallel to the z axis so the distance reduces to camera-space XY
					vec2 lineDir = worldEnd.xy - worldStart.xy;
					float t = clamp( dot( worldPos.xy - worldStart.xy, lineDir ) / dot( lineDir, lineDir ), 0.0, 1.0 );
					len = length( worldStart.xy + lineDir * t - worldPos.xy );

				} else {

					// Find the closest points on the view ray and the line segment
					vec3 rayEnd = normalize( worldPos.xyz ) * 1e5;
					vec3 lineDir = worldEnd - worldStart;
					vec2 params = closestLineToLine( worldStart, worldEnd, vec3( 0.0, 0.0, 0.0 ), rayEnd );

					vec3 p1 = worldStart + lineDir * params.x;
					vec3 p2 = rayEnd * params.y;
					vec3 delta = p1 - p2;
					len = length( delta );

				}

				float norm = len / linewidth;

				#ifndef USE_DASH

					#ifdef USE_ALPHA_TO_COVERAGE

						float dnorm = fwidth( norm );
						alpha = 1.0 - smoothstep( 0.5 - dnorm, 0.5 + dnorm, norm );

					#else

						if ( norm > 0.5 ) {

							discard;

						}

					#endif

				#endif

			#else

				#ifdef USE_ALPHA_TO_COVERAGE

					// artifacts appear on some hardware if a derivative is taken within a conditional
					float a = vUv.x;
					float b = ( vUv.y > 0.0 ) ? vUv.y - 1.0 : vUv.y + 1.0;
					float len2 = a * a + b * b;
					float dlen = fwidth( len2 );

					if ( abs( vUv.y ) > 1.0 ) {

						alpha = 1.0 - smoothstep( 1.0 - dlen, 1.0 + dlen, len2 );

					}

				#else

					if ( abs( vUv.y ) > 1.0 ) {

						float a = vUv.x;
						float b = ( vUv.y > 0.0 ) ? vUv.y - 1.0 : vUv.y + 1.0;
						float len2 = a * a + b * b;

						if ( len2 > 1.0 ) discard;

					}

				#endif

			#endif

			#include <logdepthbuf_fragment>
			#include <color_fragment>

			gl_FragColor = vec4( diffuseColor.rgb, alpha );

			#include <tonemapping_fragment>
			#include <colorspace_fragment>
			#include <fog_fragment>
			#include <premultiplied_alpha_fragment>

		}
		`};var co=class extends yi{constructor(e){super({type:"LineMaterial",uniforms:Ra.clone(Zn.line.uniforms),vertexShader:Zn.line.vertexShader,fragmentShader:Zn.line.fragmentShader,clipping:!0}),this.isLineMaterial=!0,this.setValues(e)}get color(){return this.uniforms.diffuse.value}set color(e){this.uniforms.diffuse.value=e}get worldUnits(){return"WORLD_UNITS"in this.defines}set worldUnits(e){e===!0!==this.worldUnits&&(this.needsUpdate=!0),e===!0?this.defines.WORLD_UNITS="":delete this.defines.WORLD_UNITS}get linewidth(){return this.uniforms.linewidth.value}set linewidth(e){this.uniforms.linewidth&&(this.uniforms.linewidth.value=e)}get dashed(){return"USE_DASH"in this.defines}set dashed(e){e===!0!==this.dashed&&(this.needsUpdate=!0),e===!0?this.defines.USE_DASH="":delete this.defines.USE_DASH}get dashScale(){return this.uniforms.dashScale.value}set dashScale(e){this.uniforms.dashScale.value=e}get dashSize(){return this.uniforms.dashSize.value}set dashSize(e){this.uniforms.dashSize.value=e}get dashOffset(){return this.uniforms.dashOffset.value}set dashOffset(e){this.uniforms.dashOffset.value=e}get gapSize(){return this.uniforms.gapSize.value}set gapSize(e){this.uniforms.gapSize.value=e}get opacity(){return this.uniforms.opacity.value}set opacity(e){this.uniforms&&(this.uniforms.opacity.value=e)}get resolution(){return this.uniforms.resolution.value}set resolution(e){this.uniforms.resolution.value.copy(e)}get alphaToCoverage(){return"USE_ALPHA_TO_COVERAGE"in this.defines}set alphaToCoverage(e){this.defines&&(e===!0!==this.alphaToCoverage&&(this.needsUpdate=!0),e===!0?this.defines.USE_ALPHA_TO_COVERAGE="":delete this.defines.USE_ALPHA_TO_COVERAGE)}};var rd=new Ct,_m=new W,xm=new W,In=new Ct,Ln=new Ct,ji=new Ct,od=new W,ad=new kt,Dn=new ma,vm=new W,Yc=new qn,Zc=new Pi,Qi=new Ct,es,ur;function ym(i,e,t){return Qi.set(0,0,-e,1).applyMatrix4(i.projectionMatrix),Qi.multiplyScalar(1/Qi.w),Qi.x=ur/t.width,Qi.y=ur/t.height,Qi.applyMatrix4(i.projectionMatrixInverse),Qi.multiplyScalar(1/Qi.w),Math.abs(Math.max(Qi.x,Qi.y))}function FS(i,e){let t=i.matrixWorld,n=i.geometry,s=n.attributes.instanceStart,r=n.attributes.instanceEnd,o=Math.min(n.instanceCount,s.count);for(let a=0,c=o;a<c;a++){Dn.start.fromBufferAttribute(s,a),Dn.end.fromBufferAttribute(r,a),Dn.applyMatrix4(t);let l=new W,d=new W;es.distanceSqToSegment(Dn.start,Dn.end,d,l),d.distanceTo(l)<ur*.5&&e.push({point:d,pointOnLine:l,distance:es.origin.distanceTo(d),object:i,face:null,faceIndex:a,uv:null,uv1:null})}}function OS(i,e,t){let n=e.projectionMatrix,r=i.material.resolution,o=i.matrixWorld,a=i.geometry,c=a.attributes.instanceStart,l=a.attributes.instanceEnd,d=Math.min(a.instanceCount,c.count),u=-e.near;es.at(1,ji),ji.w=1,ji.applyMatrix4(e.matrixWorldInverse),ji.applyMatrix4(n),ji.multiplyScalar(1/ji.w),ji.x*=r.x/2,ji.y*=r.y/2,ji.z=0,od.copy(ji),ad.multiplyMatrices(e.matrixWorldInverse,o);for(let h=0,m=d;h<m;h++){if(In.fromBufferAttribute(c,h),Ln.fromBufferAttribute(l,h),In.w=1,Ln.w=1,In.applyMatrix4(ad),Ln.applyMatrix4(ad),In.z>u&&Ln.z>u)continue;if(In.z>u){let C=In.z-Ln.z,M=(In.z-u)/C;In.lerp(Ln,M)}else if(Ln.z>u){let C=Ln.z-In.z,M=(Ln.z-u)/C;Ln.lerp(In,M)}In.applyMatrix4(n),Ln.applyMatrix4(n),In.multiplyScalar(1/In.w),Ln.multiplyScalar(1/Ln.w),In.x*=r.x/2,In.y*=r.y/2,Ln.x*=r.x/2,Ln.y*=r.y/2,Dn.start.copy(In),Dn.start.z=0,Dn.end.copy(Ln),Dn.end.z=0;let v=Dn.closestPointToPointParameter(od,!0);Dn.at(v,vm);let p=Aa.lerp(In.z,Ln.z,v),f=p>=-1&&p<=1,y=od.distanceTo(vm)<ur*.5;if(f&&y){Dn.start.fromBufferAttribute(c,h),Dn.end.fromBufferAttribute(l,h),Dn.start.applyMatrix4(o),Dn.end.applyMatrix4(o);let C=new W,M=new W;es.distanceSqToSegment(Dn.start,Dn.end,M,C),t.push({point:M,pointOnLine:C,distance:es.origin.distanceTo(M),object:i,face:null,faceIndex:h,uv:null,uv1:null})}}}var Jc=class extends Pn{constructor(e=new lo,t=new co({color:Math.random()*16777215})){super(e,t),this.isLineSegments2=!0,this.type="LineSegments2"}computeLineDistances(){let e=this.geometry,t=e.attributes.instanceStart,n=e.attributes.instanceEnd,s=new Float32Array(2*t.count);for(let o=0,a=0,c=t.count;o<c;o++,a+=2)_m.fromBufferAttribute(t,o),xm.fromBufferAttribute(n,o),s[a]=a===0?0:s[a-1],s[a+1]=s[a]+_m.distanceTo(xm);let r=new Vs(s,2,1);return e.setAttribute("instanceDistanceStart",new Ii(r,1,0)),e.setAttribute("instanceDistanceEnd",new Ii(r,1,1)),this}raycast(e,t){let n=this.material.worldUnits,s=e.camera;if(s===null&&!n&&console.error('LineSegments2: "Raycaster.camera" needs to be set in order to raycast against LineSegments2 while worldUnits is set to false.'),n===!1&&(this.material.resolution.x===0||this.material.resolution.y===0))return;let r=e.params.Line2!==void 0&&e.params.Line2.threshold||0;es=e.ray;let o=this.matrixWorld,a=this.geometry,c=this.material;ur=c.linewidth+r,a.boundingSphere===null&&a.computeBoundingSphere(),Zc.copy(a.boundingSphere).applyMatrix4(o);let l;if(n)l=ur*.5;else{let u=Math.max(s.near,Zc.distanceToPoint(es.origin));l=ym(s,u,c.resolution)}if(Zc.radius+=l,es.intersectsSphere(Zc)===!1)return;a.boundingBox===null&&a.computeBoundingBox(),Yc.copy(a.boundingBox).applyMatrix4(o);let d;if(n)d=ur*.5;else{let u=Math.max(s.near,Yc.distanceToPoint(es.origin));d=ym(s,u,c.resolution)}Yc.expandByScalar(d),es.intersectsBox(Yc)!==!1&&(n?FS(this,t):OS(this,s,t))}onBeforeRender(e){let t=this.material.uniforms;t&&t.resolution&&(e.getViewport(rd),this.material.uniforms.resolution.value.set(rd.z,rd.w))}};var Kc=[[49,54,149],[69,117,180],[116,173,209],[171,217,233],[224,243,248],[255,255,191],[254,224,144],[253,174,97],[244,109,67],[215,48,39],[165,0,38]],BS=[107,114,128];function ho(i){if(i==null||!Number.isFinite(i))return BS;let e=Math.min(1,Math.max(0,i))*(Kc.length-1),t=Math.min(Kc.length-2,Math.floor(e)),n=e-t,s=Kc[t],r=Kc[t+1];return[0,1,2].map(o=>Math.round(s[o]+(r[o]-s[o])*n))}function jc(i){let[e,t,n]=ho(i);return`rgb(${e},${t},${n})`}var uo=7;function Qc(i){return jc((i-1)/(uo-1))}function ld(i,e){return jc(e>1?(i-1)/(e-1):0)}var kS=new Set([0,1,2,3,4,5,6,7,8,9,10]),zS=new Set([17,18,19,20,21,22]),VS=856601;function HS(){try{let i=document.createElement("canvas");return!!(i.getContext("webgl2")||i.getContext("webgl"))}catch{return!1}}var eh=class{constructor(e){if(this.container=e,this.session=null,this.frame=0,this.time=0,this.renderPending=!1,this.ok=HS(),this.ok)this.renderer=new Hc({antialias:!0}),this.renderer.setPixelRatio(Math.min(window.devicePixelRatio||1,2)),this.renderer.setClearColor(VS,1),this.canvas=this.renderer.domElement;else{this.canvas=document.createElement("canvas");let n=document.createElement("div");n.className="view-message",n.textContent="The 3D view needs WebGL, which this browser does not provide. The plots below still work.",e.appendChild(n)}if(this.canvas.classList.add("view3d"),this.canvas.setAttribute("data-frame","0"),this.canvas.setAttribute("aria-label","3D view of the operator skeleton"),e.prepend(this.canvas),!this.ok)return;this.scene=new Ko,this.camera=new $n(40,1,.02,200),this.controls=new Xc(this.camera,this.canvas),this.controls.addEventListener("change",()=>this.requestRender()),this.scene.add(new ha(14674165,2765632,2.2));let t=new fa(16777215,1.6);t.position.set(3,-4,6),this.scene.add(t),this.world=new Yi,this.scene.add(this.world),new ResizeObserver(()=>this.resize()).observe(e),this.resize()}resize(){if(!this.ok)return;let e=Math.max(1,this.container.clientWidth),t=Math.max(1,this.container.clientHeight);this.renderer.setSize(e,t),this.camera.aspect=e/t,this.camera.updateProjectionMatrix(),this.boneMaterial&&this.boneMaterial.resolution.set(e,t),this.requestRender()}setSession(e){if(this.session=e,!this.ok)return;for(let F of[...this.world.children])this.world.remove(F),F.traverse(B=>{B.geometry&&B.geometry.dispose(),B.material&&B.material.dispose()});let t=e,n=new W(...t.up);this.camera.up.copy(n);let s=new qn,r=new W,o=[],a=[],c=[],l=[],d=Math.max(1,Math.floor(t.n/300));for(let F=0;F<t.n;F+=d){let B=t.positions[F];for(let D=0;D<t.nl;D++)Number.isNaN(B[3*D])||(o.push(B[3*D]),a.push(B[3*D+1]),c.push(B[3*D+2]),l.push(B[3*D]*n.x+B[3*D+1]*n.y+B[3*D+2]*n.z))}let u=(F,B)=>F[Math.min(F.length-1,Math.max(0,Math.round(B*(F.length-1))))];for(let F of[o,a,c,l])F.sort((B,D)=>B-D);let h=1/0;o.length&&(s.set(new W(u(o,.02),u(a,.02),u(c,.02)),new W(u(o,.98),u(a,.98),u(c,.98))),h=u(l,.01));let m=s.clone();if(t.tcp)for(let F of t.tcp.positions)s.expandByPoint(r.set(...F));t.handover&&s.expandByPoint(r.set(...t.handover)),s.isEmpty()&&s.set(new W(-1,-1,0),new W(1,1,2)),Number.isFinite(h)||(h=s.min.dot(n));let g=s.getCenter(new W),v=Math.max(.8,s.getSize(new W).length()/2),p=new W(1,0,0).projectOnPlane(n);p.lengthSq()<1e-6&&p.set(0,1,0).projectOnPlane(n),p.normalize();let f=new W().crossVectors(n,p).normalize(),y=Math.max(3,Math.ceil(v*2.6)),C=new ga(y,y*4,3820127,2239802);C.quaternion.setFromUnitVectors(new W(0,1,0),n);let M=g.clone().projectOnPlane(n).addScaledVector(n,h);C.position.copy(M),this.world.add(C);let R=new _a(.25);R.position.copy(new W().projectOnPlane(n).addScaledVector(n,h+.002)),this.world.add(R);let b=new ra(1,20,14);this.spheres=[];for(let F=0;F<t.nl;F++){let B=new Pn(b,new rr({roughness:.45,metalness:0})),D=kS.has(F)?.011:zS.has(F)?.012:.022;B.scale.setScalar(D),B.visible=!1,this.spheres.push(B),this.world.add(B)}if(this.boneGeometry=new lo,this.bonePos=new Float32Array(Math.max(1,t.bones.length)*6),this.boneCol=new Float32Array(Math.max(1,t.bones.length)*6),this.boneGeometry.setPositions(this.bonePos),this.boneGeometry.setColors(this.boneCol),this.boneMaterial=new co({linewidth:3.5,vertexColors:!0,worldUnits:!1}),this.boneMaterial.resolution.set(this.container.clientWidth||1,this.container.clientHeight||1),this.bones=new Jc(this.boneGeometry,this.boneMaterial),this.bones.frustumCulled=!1,this.world.add(this.bones),this.tcpTrail=null,this.tcpMarker=null,t.tcp){let F=new Float32Array(t.tcp.positions.flat()),B=new An;B.setAttribute("position",new Kn(F,3)),this.world.add(new sr(B,new xs({color:16756768,transparent:!0,opacity:.22})));let D=new An;D.setAttribute("position",new Kn(F.slice(),3)),this.tcpTrail=new sr(D,new xs({color:16756768})),this.tcpTrail.frustumCulled=!1,this.world.add(this.tcpTrail),this.tcpMarker=new Pn(b,new rr({color:16756768,emissive:5583616,roughness:.3})),this.tcpMarker.scale.setScalar(.03),this.world.add(this.tcpMarker)}if(t.handover){let F=new Yi,B=new Pn(b,new rr({color:3724191,emissive:735786}));B.scale.setScalar(.015),F.add(B);let D=new Pn(new oa(.05,.004,8,40),new jr({color:3724191}));D.quaternion.setFromUnitVectors(new W(0,0,1),n),F.add(D),F.position.set(...t.handover),this.world.add(F)}let _=m.isEmpty()?g:m.getCenter(new W).lerp(g,.35),A=new W().addScaledVector(p,.62).addScaledVector(f,-.72).addScaledVector(n,.32).normalize(),H=this.camera.fov*Math.PI/180,O=2*Math.atan(Math.tan(H/2)*Math.max(.5,this.camera.aspect||1)),T=Math.min(H,O)/2;this.camera.position.copy(_).addScaledVector(A,v*.9/Math.sin(T)),this.camera.near=.01,this.camera.far=v*40,this.camera.updateProjectionMatrix(),this.controls.target.copy(_),this.controls.update(),this.requestRender()}setFrame(e){this.frame=e;let t=this.session;this.time=t&&t.n?t.t[e]:0,this.requestRender()}requestRender(){this.renderPending||(this.renderPending=!0,requestAnimationFrame(()=>{this.renderPending=!1,this.render()}))}render(){let e=this.session;if(this.ok&&e){let t=new ct;if(e.n){let n=e.positions[this.frame],s=e.strain[this.frame];for(let r=0;r<e.nl;r++){let o=this.spheres[r];if(Number.isNaN(n[3*r])){o.visible=!1;continue}o.visible=!0,o.position.set(n[3*r],n[3*r+1],n[3*r+2]);let[a,c,l]=ho(s[r]);o.material.color.setRGB(a/255,c/255,l/255,On)}e.bones.forEach(([r,o],a)=>{let c=!Number.isNaN(n[3*r])&&!Number.isNaN(n[3*o]);for(let l=0;l<2;l++){let d=l?o:r;for(let g=0;g<3;g++)this.bonePos[6*a+3*l+g]=c?n[3*d+g]:0;let[u,h,m]=ho(s[d]);t.setRGB(u/255,h/255,m/255,On),this.boneCol[6*a+3*l]=t.r,this.boneCol[6*a+3*l+1]=t.g,this.boneCol[6*a+3*l+2]=t.b}}),this.boneGeometry.attributes.instanceStart.data.needsUpdate=!0,this.boneGeometry.attributes.instanceColorStart.data.needsUpdate=!0}else for(let n of this.spheres)n.visible=!1;if(e.tcp&&this.tcpMarker){let n=e.tcp.t,s=this.time,r=Cr(n,s),o=e.tcp.positions[r];if(s>n[r]&&r+1<n.length){let a=(s-n[r])/(n[r+1]-n[r]),c=e.tcp.positions[r+1];o=[0,1,2].map(l=>o[l]+(c[l]-o[l])*a)}this.tcpMarker.position.set(...o),this.tcpTrail.geometry.setDrawRange(0,s>=n[0]?r+1:0)}this.renderer.render(this.scene,this.camera)}this.canvas.setAttribute("data-frame",String(this.frame))}};var GS="uplot",WS="u-hz",$S="u-vt",XS="u-title",qS="u-wrap",YS="u-under",ZS="u-over",JS="u-axis",pr="u-off",KS="u-select",jS="u-cursor-x",QS="u-cursor-y",eM="u-cursor-pt",tM="u-legend",nM="u-live",iM="u-inline",sM="u-series",rM="u-marker",bm="u-label",oM="u-value",Na="width",Ua="height";var Sm="bottom",fo="left",cd="right",Td="#000",Mm=Td+"0",hd="mousemove",wm="mousedown",ud="mouseup",Em="mouseenter",Tm="mouseleave",Am="dblclick",aM="resize",lM="scroll",Rm="change",rh="dppxchange",Ad="--",yo=typeof window<"u",gd=yo?document:null,mo=yo?window:null,cM=yo?navigator:null,Tt,th;function _d(){let i=devicePixelRatio;Tt!=i&&(Tt=i,th&&vd(Rm,th,_d),th=matchMedia(`(min-resolution: ${Tt-.001}dppx) and (max-resolution: ${Tt+.001}dppx)`),mr(Rm,th,_d),mo.dispatchEvent(new CustomEvent(rh)))}function di(i,e){if(e!=null){let t=i.classList;!t.contains(e)&&t.add(e)}}function xd(i,e){let t=i.classList;t.contains(e)&&t.remove(e)}function qt(i,e,t){i.style[e]=t+"px"}function Fi(i,e,t,n){let s=gd.createElement(i);return e!=null&&di(s,e),t?.insertBefore(s,n),s}function bi(i,e){return Fi("div",i,e)}var Cm=new WeakMap;function ts(i,e,t,n,s){let r="translate("+e+"px,"+t+"px)",o=Cm.get(i);r!=o&&(i.style.transform=r,Cm.set(i,r),e<0||t<0||e>n||t>s?di(i,pr):xd(i,pr))}var Pm=new WeakMap;function Im(i,e,t){let n=e+t,s=Pm.get(i);n!=s&&(Pm.set(i,n),i.style.background=e,i.style.borderColor=t)}var Lm=new WeakMap;function Dm(i,e,t,n){let s=e+""+t,r=Lm.get(i);s!=r&&(Lm.set(i,s),i.style.height=t+"px",i.style.width=e+"px",i.style.marginLeft=n?-e/2+"px":0,i.style.marginTop=n?-t/2+"px":0)}var Rd={passive:!0},hM={...Rd,capture:!0};function mr(i,e,t,n){e.addEventListener(i,t,n?hM:Rd)}function vd(i,e,t,n){e.removeEventListener(i,t,Rd)}yo&&_d();function Oi(i,e,t,n){let s;t=t||0,n=n||e.length-1;let r=n<=2147483647;for(;n-t>1;)s=r?t+n>>1:fi((t+n)/2),e[s]<i?t=s:n=s;return i-e[t]<=e[n]-i?t:n}function ag(i){return(t,n,s)=>{let r=-1,o=-1;for(let a=n;a<=s;a++)if(i(t[a])){r=a;break}for(let a=s;a>=n;a--)if(i(t[a])){o=a;break}return[r,o]}}var lg=i=>i!=null,cg=i=>i!=null&&i>0,lh=ag(lg),uM=ag(cg);function dM(i,e,t,n=0,s=!1){let r=s?uM:lh,o=s?cg:lg;[e,t]=r(i,e,t);let a=i[e],c=i[e];if(e>-1)if(n==1)a=i[e],c=i[t];else if(n==-1)a=i[t],c=i[e];else for(let l=e;l<=t;l++){let d=i[l];o(d)&&(d<a?a=d:d>c&&(c=d))}return[a??zt,c??-zt]}function ch(i,e,t,n){let s=Fm(i),r=Fm(e);i==e&&(s==-1?(i*=t,e/=t):(i/=t,e*=t));let o=t==10?Ms:hg,a=s==1?fi:Si,c=r==1?Si:fi,l=a(o(vn(i))),d=c(o(vn(e))),u=go(t,l),h=go(t,d);return t==10&&(l<0&&(u=Vt(u,-l)),d<0&&(h=Vt(h,-d))),n||t==2?(i=u*s,e=h*r):(i=pg(i,u),e=hh(e,h)),[i,e]}function Cd(i,e,t,n){let s=ch(i,e,t,n);return i==0&&(s[0]=0),e==0&&(s[1]=0),s}var Pd=.1,Nm={mode:3,pad:Pd},Oa={pad:0,soft:null,mode:0},fM={min:Oa,max:Oa};function oh(i,e,t,n){return uh(t)?Um(i,e,t):(Oa.pad=t,Oa.soft=n?0:null,Oa.mode=n?3:0,Um(i,e,fM))}function Mt(i,e){return i??e}function pM(i,e,t){for(e=Mt(e,0),t=Mt(t,i.length-1);e<=t;){if(i[e]!=null)return!0;e++}return!1}function Um(i,e,t){let n=t.min,s=t.max,r=Mt(n.pad,0),o=Mt(s.pad,0),a=Mt(n.hard,-zt),c=Mt(s.hard,zt),l=Mt(n.soft,zt),d=Mt(s.soft,-zt),u=Mt(n.mode,0),h=Mt(s.mode,0),m=e-i,g=Ms(m),v=Jn(vn(i),vn(e)),p=Ms(v),f=vn(p-g);(m<1e-24||f>10)&&(m=0,(i==0||e==0)&&(m=1e-24,u==2&&l!=zt&&(r=0),h==2&&d!=-zt&&(o=0)));let y=m||v||1e3,C=Ms(y),M=go(10,fi(C)),R=y*(m==0?i==0?.1:1:r),b=Vt(pg(i-R,M/10),24),_=i>=l&&(u==1||u==3&&b<=l||u==2&&b>=l)?l:zt,A=Jn(a,b<_&&i>=_?_:Bi(_,b)),H=y*(m==0?e==0?.1:1:o),O=Vt(hh(e+H,M/10),24),T=e<=d&&(h==1||h==3&&O>=d||h==2&&O<=d)?d:-zt,F=Bi(c,O>T&&e<=T?T:Jn(T,O));return A==F&&A==0&&(F=100),[A,F]}var mM=new Intl.NumberFormat(yo?cM.language:"en-US"),Id=i=>mM.format(i),pi=Math,sh=pi.PI,vn=pi.abs,fi=pi.floor,xn=pi.round,Si=pi.ceil,Bi=pi.min,Jn=pi.max,go=pi.pow,Fm=pi.sign,Ms=pi.log10,hg=pi.log2,gM=(i,e=1)=>pi.sinh(i)*e,dd=(i,e=1)=>pi.asinh(i/e),zt=1/0;function Om(i){return(Ms((i^i>>31)-(i>>31))|0)+1}function yd(i,e,t){return Bi(Jn(i,e),t)}function ug(i){return typeof i=="function"}function xt(i){return ug(i)?i:()=>i}var _M=()=>{},dg=i=>i,fg=(i,e)=>e,xM=i=>null,Bm=i=>!0,km=(i,e)=>i==e,vM=/\.\d*?(?=9{6,}|0{6,})/gm,gr=i=>{if(gg(i)||Ys.has(i))return i;let e=`${i}`,t=e.match(vM);if(t==null)return i;let n=t[0].length-1;if(e.indexOf("e-")!=-1){let[s,r]=e.split("e");return+`${gr(s)}e${r}`}return Vt(i,n)};function dr(i,e){return gr(Vt(gr(i/e))*e)}function hh(i,e){return gr(Si(gr(i/e))*e)}function pg(i,e){return gr(fi(gr(i/e))*e)}function Vt(i,e=0){if(gg(i))return i;let t=10**e,n=i*t*(1+Number.EPSILON);return xn(n)/t}var Ys=new Map;function mg(i){return((""+i).split(".")[1]||"").length}function ka(i,e,t,n){let s=[],r=n.map(mg);for(let o=e;o<t;o++){let a=vn(o),c=Vt(go(i,o),a);for(let l=0;l<n.length;l++){let d=i==10?+`${n[l]}e${o}`:n[l]*c,u=(o>=0?0:a)+(o>=r[l]?0:r[l]),h=i==10?d:Vt(d,u);s.push(h),Ys.set(h,u)}}return s}var Ba={},Ld=[],_o=[null,null],qs=Array.isArray,gg=Number.isInteger,yM=i=>i===void 0;function zm(i){return typeof i=="string"}function uh(i){let e=!1;if(i!=null){let t=i.constructor;e=t==null||t==Object}return e}function bM(i){return i!=null&&typeof i=="object"}var SM=Object.getPrototypeOf(Uint8Array),_g="__proto__";function xo(i,e=uh){let t;if(qs(i)){let n=i.find(s=>s!=null);if(qs(n)||e(n)){t=Array(i.length);for(let s=0;s<i.length;s++)t[s]=xo(i[s],e)}else t=i.slice()}else if(i instanceof SM)t=i.slice();else if(e(i)){t={};for(let n in i)n!=_g&&(t[n]=xo(i[n],e))}else t=i;return t}function un(i){let e=arguments;for(let t=1;t<e.length;t++){let n=e[t];for(let s in n)s!=_g&&(uh(i[s])?un(i[s],xo(n[s])):i[s]=xo(n[s]))}return i}var MM=0,wM=1,EM=2;function TM(i,e,t){for(let n=0,s,r=-1;n<e.length;n++){let o=e[n];if(o>r){for(s=o-1;s>=0&&i[s]==null;)i[s--]=null;for(s=o+1;s<t&&i[s]==null;)i[r=s++]=null}}}function AM(i,e){if(PM(i)){let o=i[0].slice();for(let a=1;a<i.length;a++)o.push(...i[a].slice(1));return IM(o[0])||(o=CM(o)),o}let t=new Set;for(let o=0;o<i.length;o++){let c=i[o][0],l=c.length;for(let d=0;d<l;d++)t.add(c[d])}let n=[Array.from(t).sort((o,a)=>o-a)],s=n[0].length,r=new Map;for(let o=0;o<s;o++)r.set(n[0][o],o);for(let o=0;o<i.length;o++){let a=i[o],c=a[0];for(let l=1;l<a.length;l++){let d=a[l],u=Array(s).fill(void 0),h=e?e[o][l]:wM,m=[];for(let g=0;g<d.length;g++){let v=d[g],p=r.get(c[g]);v===null?h!=MM&&(u[p]=v,h==EM&&m.push(p)):u[p]=v}TM(u,m,s),n.push(u)}}return n}var RM=typeof queueMicrotask>"u"?i=>Promise.resolve().then(i):queueMicrotask;function CM(i){let e=i[0],t=e.length,n=Array(t);for(let r=0;r<n.length;r++)n[r]=r;n.sort((r,o)=>e[r]-e[o]);let s=[];for(let r=0;r<i.length;r++){let o=i[r],a=Array(t);for(let c=0;c<t;c++)a[c]=o[n[c]];s.push(a)}return s}function PM(i){let e=i[0][0],t=e.length;for(let n=1;n<i.length;n++){let s=i[n][0];if(s.length!=t)return!1;if(s!=e){for(let r=0;r<t;r++)if(s[r]!=e[r])return!1}}return!0}function IM(i,e=100){let t=i.length;if(t<=1)return!0;let n=0,s=t-1;for(;n<=s&&i[n]==null;)n++;for(;s>=n&&i[s]==null;)s--;if(s<=n)return!0;let r=Jn(1,fi((s-n+1)/e));for(let o=i[n],a=n+r;a<=s;a+=r){let c=i[a];if(c!=null){if(c<=o)return!1;o=c}}return!0}var xg=["January","February","March","April","May","June","July","August","September","October","November","December"],vg=["Sunday","Monday","Tuesday","Wednesday","Thursday","Friday","Saturday"];function yg(i){return i.slice(0,3)}var LM=vg.map(yg),DM=xg.map(yg),NM={MMMM:xg,MMM:DM,WWWW:vg,WWW:LM};function Da(i){return(i<10?"0":"")+i}function UM(i){return(i<10?"00":i<100?"0":"")+i}var FM={YYYY:i=>i.getFullYear(),YY:i=>(i.getFullYear()+"").slice(2),MMMM:(i,e)=>e.MMMM[i.getMonth()],MMM:(i,e)=>e.MMM[i.getMonth()],MM:i=>Da(i.getMonth()+1),M:i=>i.getMonth()+1,DD:i=>Da(i.getDate()),D:i=>i.getDate(),WWWW:(i,e)=>e.WWWW[i.getDay()],WWW:(i,e)=>e.WWW[i.getDay()],HH:i=>Da(i.getHours()),H:i=>i.getHours(),h:i=>{let e=i.getHours();return e==0?12:e>12?e-12:e},AA:i=>i.getHours()>=12?"PM":"AM",aa:i=>i.getHours()>=12?"pm":"am",a:i=>i.getHours()>=12?"p":"a",mm:i=>Da(i.getMinutes()),m:i=>i.getMinutes(),ss:i=>Da(i.getSeconds()),s:i=>i.getSeconds(),fff:i=>UM(i.getMilliseconds())};function Dd(i,e){e=e||NM;let t=[],n=/\{([a-z]+)\}|[^{]+/gi,s;for(;s=n.exec(i);)t.push(s[0][0]=="{"?FM[s[1]]:s[0]);return r=>{let o="";for(let a=0;a<t.length;a++)o+=typeof t[a]=="string"?t[a]:t[a](r,e);return o}}var OM=new Intl.DateTimeFormat().resolvedOptions().timeZone;function BM(i,e){let t;return e=="UTC"||e=="Etc/UTC"?t=new Date(+i+i.getTimezoneOffset()*6e4):e==OM?t=i:(t=new Date(i.toLocaleString("en-US",{timeZone:e})),t.setMilliseconds(i.getMilliseconds())),t}var bg=i=>i%1==0,ah=[1,2,2.5,5],kM=ka(10,-32,0,ah),Sg=ka(10,0,32,ah),zM=Sg.filter(bg),fr=kM.concat(Sg),Nd=`
`,Mg="{YYYY}",Vm=Nd+Mg,wg="{M}/{D}",Fa=Nd+wg,nh=Fa+"/{YY}",Eg="{aa}",VM="{h}:{mm}",po=VM+Eg,Hm=Nd+po,Gm=":{ss}",Pt=null;function Tg(i){let e=i*1e3,t=e*60,n=t*60,s=n*24,r=s*30,o=s*365,c=(i==1?ka(10,0,3,ah).filter(bg):ka(10,-3,0,ah)).concat([e,e*5,e*10,e*15,e*30,t,t*5,t*10,t*15,t*30,n,n*2,n*3,n*4,n*6,n*8,n*12,s,s*2,s*3,s*4,s*5,s*6,s*7,s*8,s*9,s*10,s*15,r,r*2,r*3,r*4,r*6,o,o*2,o*5,o*10,o*25,o*50,o*100]),l=[[o,Mg,Pt,Pt,Pt,Pt,Pt,Pt,1],[s*28,"{MMM}",Vm,Pt,Pt,Pt,Pt,Pt,1],[s,wg,Vm,Pt,Pt,Pt,Pt,Pt,1],[n,"{h}"+Eg,nh,Pt,Fa,Pt,Pt,Pt,1],[t,po,nh,Pt,Fa,Pt,Pt,Pt,1],[e,Gm,nh+" "+po,Pt,Fa+" "+po,Pt,Hm,Pt,1],[i,Gm+".{fff}",nh+" "+po,Pt,Fa+" "+po,Pt,Hm,Pt,1]];function d(u){return(h,m,g,v,p,f)=>{let y=[],C=p>=o,M=p>=r&&p<o,R=u(g),b=Vt(R*i,3),_=fd(R.getFullYear(),C?0:R.getMonth(),M||C?1:R.getDate()),A=Vt(_*i,3);if(M||C){let H=M?p/r:0,O=C?p/o:0,T=b==A?b:Vt(fd(_.getFullYear()+O,_.getMonth()+H,1)*i,3),F=new Date(xn(T/i)),B=F.getFullYear(),D=F.getMonth();for(let V=0;T<=v;V++){let Y=fd(B+O*V,D+H*V,1),$=Y-u(Vt(Y*i,3));T=Vt((+Y+$)*i,3),T<=v&&y.push(T)}}else{let H=p>=s?s:p,O=fi(g)-fi(b),T=A+O+hh(b-A,H);y.push(T);let F=u(T),B=F.getHours()+F.getMinutes()/t+F.getSeconds()/n,D=p/n,V=h.axes[m]._space,Y=f/V;for(;T=Vt(T+p,i==1?0:3),!(T>v);)if(D>1){let $=fi(Vt(B+D,6))%24,I=u(T).getHours()-$;I>1&&(I=-1),T-=I*n,B=(B+D)%24;let q=y[y.length-1];Vt((T-q)/p,3)*Y>=.7&&y.push(T)}else y.push(T)}return y}}return[c,l,d]}var[HM,GM,WM]=Tg(1),[$M,XM,qM]=Tg(.001);ka(2,-53,53,[1]);function Wm(i,e){return i.map(t=>t.map((n,s)=>s==0||s==8||n==null?n:e(s==1||t[8]==0?n:t[1]+n)))}function $m(i,e){return(t,n,s,r,o)=>{let a=e.find(g=>o>=g[0])||e[e.length-1],c,l,d,u,h,m;return n.map(g=>{let v=i(g),p=v.getFullYear(),f=v.getMonth(),y=v.getDate(),C=v.getHours(),M=v.getMinutes(),R=v.getSeconds(),b=p!=c&&a[2]||f!=l&&a[3]||y!=d&&a[4]||C!=u&&a[5]||M!=h&&a[6]||R!=m&&a[7]||a[1];return c=p,l=f,d=y,u=C,h=M,m=R,b(v)})}}function YM(i,e){let t=Dd(e);return(n,s,r,o,a)=>s.map(c=>t(i(c)))}function fd(i,e,t){return new Date(i,e,t)}function Xm(i,e){return e(i)}var ZM="{YYYY}-{MM}-{DD} {h}:{mm}{aa}";function qm(i,e){return(t,n,s,r)=>r==null?Ad:e(i(n))}function JM(i,e){let t=i.series[e];return t.width?t.stroke(i,e):t.points.width?t.points.stroke(i,e):null}function KM(i,e){return i.series[e].fill(i,e)}var jM={show:!0,live:!0,isolate:!1,mount:_M,markers:{show:!0,width:2,stroke:JM,fill:KM,dash:"solid"},idx:null,idxs:null,values:[]};function QM(i,e){let t=i.cursor.points,n=bi(),s=t.size(i,e);qt(n,Na,s),qt(n,Ua,s);let r=s/-2;qt(n,"marginLeft",r),qt(n,"marginTop",r);let o=t.width(i,e,s);return o&&qt(n,"borderWidth",o),n}function ew(i,e){let t=i.series[e].points;return t._fill||t._stroke}function tw(i,e){let t=i.series[e].points;return t._stroke||t._fill}function nw(i,e){return i.series[e].points.size}var pd=[0,0];function iw(i,e,t){return pd[0]=e,pd[1]=t,pd}function ih(i,e,t,n=!0){return s=>{s.button==0&&(!n||s.target==e)&&t(s)}}function md(i,e,t,n=!0){return s=>{(!n||s.target==e)&&t(s)}}var sw={show:!0,x:!0,y:!0,lock:!1,move:iw,points:{one:!1,show:QM,size:nw,width:0,stroke:tw,fill:ew},bind:{mousedown:ih,mouseup:ih,click:ih,dblclick:ih,mousemove:md,mouseleave:md,mouseenter:md},drag:{setScale:!0,x:!0,y:!1,dist:0,uni:null,click:(i,e)=>{e.stopPropagation(),e.stopImmediatePropagation()},_x:!1,_y:!1},focus:{dist:(i,e,t,n,s)=>n-s,prox:-1,bias:0},hover:{skip:[void 0],prox:null,bias:0},left:-10,top:-10,idx:null,dataIdx:null,idxs:null,event:null},Ag={show:!0,stroke:"rgba(0,0,0,0.07)",width:2},Ud=un({},Ag,{filter:fg}),Rg=un({},Ud,{size:10}),Cg=un({},Ag,{show:!1}),Fd='12px system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, "Noto Sans", sans-serif, "Apple Color Emoji", "Segoe UI Emoji", "Segoe UI Symbol", "Noto Color Emoji"',Pg="bold "+Fd,Ig=1.5,Ym={show:!0,scale:"x",stroke:Td,space:50,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Pg,side:2,grid:Ud,ticks:Rg,border:Cg,font:Fd,lineGap:Ig,rotate:0},rw="Value",ow="Time",Zm={show:!0,scale:"x",auto:!1,sorted:1,min:zt,max:-zt,idxs:[]};function aw(i,e,t,n,s){return e.map(r=>r==null?"":Id(r))}function lw(i,e,t,n,s,r,o){let a=[],c=Ys.get(s)||0;t=o?t:Vt(hh(t,s),c);for(let l=t;l<=n;l=Vt(l+s,c))a.push(Object.is(l,-0)?0:l);return a}function bd(i,e,t,n,s,r,o){let a=[],c=i.scales[i.axes[e].scale].log,l=c==10?Ms:hg,d=fi(l(t));s=go(c,d),c==10&&(s=fr[Oi(s,fr)]);let u=t,h=s*c;c==10&&(h=fr[Oi(h,fr)]);do a.push(u),u=u+s,c==10&&!Ys.has(u)&&(u=Vt(u,Ys.get(s))),u>=h&&(s=u,h=s*c,c==10&&(h=fr[Oi(h,fr)]));while(u<=n);return a}function cw(i,e,t,n,s,r,o){let c=i.scales[i.axes[e].scale].asinh,l=n>c?bd(i,e,Jn(c,t),n,s):[c],d=n>=0&&t<=0?[0]:[];return(t<-c?bd(i,e,Jn(c,-n),-t,s):[c]).reverse().map(h=>-h).concat(d,l)}var Lg=/./,hw=/[12357]/,uw=/[125]/,Jm=/1/,Sd=(i,e,t,n)=>i.map((s,r)=>e==4&&s==0||r%n==0&&t.test(s.toExponential()[s<0?1:0])?s:null);function dw(i,e,t,n,s){let r=i.axes[t],o=r.scale,a=i.scales[o],c=i.valToPos,l=r._space,d=c(10,o),u=c(9,o)-d>=l?Lg:c(7,o)-d>=l?hw:c(5,o)-d>=l?uw:Jm;if(u==Jm){let h=vn(c(1,o)-d);if(h<l)return Sd(e.slice().reverse(),a.distr,u,Si(l/h)).reverse()}return Sd(e,a.distr,u,1)}function fw(i,e,t,n,s){let r=i.axes[t],o=r.scale,a=r._space,c=i.valToPos,l=vn(c(1,o)-c(2,o));return l<a?Sd(e.slice().reverse(),3,Lg,Si(a/l)).reverse():e}function pw(i,e,t,n){return n==null?Ad:e==null?"":Id(e)}var Km={show:!0,scale:"y",stroke:Td,space:30,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Pg,side:3,grid:Ud,ticks:Rg,border:Cg,font:Fd,lineGap:Ig,rotate:0};function mw(i,e){let t=3+(i||1)*2;return Vt(t*e,3)}function gw(i,e){let{scale:t,idxs:n}=i.series[0],s=i._data[0],r=i.valToPos(s[n[0]],t,!0),o=i.valToPos(s[n[1]],t,!0),a=vn(o-r),c=i.series[e],l=a/(c.points.space*Tt);return n[1]-n[0]<=l}var jm={scale:null,auto:!0,sorted:0,min:zt,max:-zt},Dg=(i,e,t,n,s)=>s,Qm={show:!0,auto:!0,sorted:0,gaps:Dg,alpha:1,facets:[un({},jm,{scale:"x"}),un({},jm,{scale:"y"})]},eg={scale:"y",auto:!0,sorted:0,show:!0,spanGaps:!1,gaps:Dg,alpha:1,points:{show:gw,filter:null},values:null,min:zt,max:-zt,idxs:[],path:null,clip:null};function _w(i,e,t,n,s){return t/10}var Ng={time:!0,auto:!0,distr:1,log:10,asinh:1,min:null,max:null,dir:1,ori:0},xw=un({},Ng,{time:!1,ori:1}),tg={};function Ug(i,e){let t=tg[i];return t||(t={key:i,plots:[],sub(n){t.plots.push(n)},unsub(n){t.plots=t.plots.filter(s=>s!=n)},pub(n,s,r,o,a,c,l){for(let d=0;d<t.plots.length;d++)t.plots[d]!=s&&t.plots[d].pub(n,s,r,o,a,c,l)}},i!=null&&(tg[i]=t)),t}var vo=1,Md=2;function _r(i,e,t){let n=i.mode,s=i.series[e],r=n==2?i._data[e]:i._data,o=i.scales,a=i.bbox,c=r[0],l=n==2?r[1]:r[e],d=n==2?o[s.facets[0].scale]:o[i.series[0].scale],u=n==2?o[s.facets[1].scale]:o[s.scale],h=a.left,m=a.top,g=a.width,v=a.height,p=i.valToPosH,f=i.valToPosV;return d.ori==0?t(s,c,l,d,u,p,f,h,m,g,v,fh,bo,mh,Og,kg):t(s,c,l,d,u,f,p,m,h,v,g,ph,So,kd,Bg,zg)}function Od(i,e){let t=0,n=0,s=Mt(i.bands,Ld);for(let r=0;r<s.length;r++){let o=s[r];o.series[0]==e?t=o.dir:o.series[1]==e&&(o.dir==1?n|=1:n|=2)}return[t,n==1?-1:n==2?1:n==3?2:0]}function vw(i,e,t,n,s){let r=i.mode,o=i.series[e],a=r==2?o.facets[1].scale:o.scale,c=i.scales[a];return s==-1?c.min:s==1?c.max:c.distr==3?c.dir==1?c.min:c.max:0}function ws(i,e,t,n,s,r){return _r(i,e,(o,a,c,l,d,u,h,m,g,v,p)=>{let f=o.pxRound,y=l.dir*(l.ori==0?1:-1),C=l.ori==0?bo:So,M,R;y==1?(M=t,R=n):(M=n,R=t);let b=f(u(a[M],l,v,m)),_=f(h(c[M],d,p,g)),A=f(u(a[R],l,v,m)),H=f(h(r==1?d.max:d.min,d,p,g)),O=new Path2D(s);return C(O,A,H),C(O,b,H),C(O,b,_),O})}function dh(i,e,t,n,s,r){let o=null;if(i.length>0){o=new Path2D;let a=e==0?mh:kd,c=t;for(let u=0;u<i.length;u++){let h=i[u];if(h[1]>h[0]){let m=h[0]-c;m>0&&a(o,c,n,m,n+r),c=h[1]}}let l=t+s-c,d=10;l>0&&a(o,c,n-d/2,l,n+r+d)}return o}function yw(i,e,t){let n=i[i.length-1];n&&n[0]==e?n[1]=t:i.push([e,t])}function Bd(i,e,t,n,s,r,o){let a=[],c=i.length;for(let l=s==1?t:n;l>=t&&l<=n;l+=s)if(e[l]===null){let u=l,h=l;if(s==1)for(;++l<=n&&e[l]===null;)h=l;else for(;--l>=t&&e[l]===null;)h=l;let m=r(i[u]),g=h==u?m:r(i[h]),v=u-s;m=o<=0&&v>=0&&v<c?r(i[v]):m;let f=h+s;g=o>=0&&f>=0&&f<c?r(i[f]):g,g>=m&&a.push([m,g])}return a}function ng(i){return i==0?dg:i==1?xn:e=>dr(e,i)}function Fg(i){let e=i==0?fh:ph,t=i==0?(s,r,o,a,c,l)=>{s.arcTo(r,o,a,c,l)}:(s,r,o,a,c,l)=>{s.arcTo(o,r,c,a,l)},n=i==0?(s,r,o,a,c)=>{s.rect(r,o,a,c)}:(s,r,o,a,c)=>{s.rect(o,r,c,a)};return(s,r,o,a,c,l=0,d=0)=>{l==0&&d==0?n(s,r,o,a,c):(l=Bi(l,a/2,c/2),d=Bi(d,a/2,c/2),e(s,r+l,o),t(s,r+a,o,r+a,o+c,l),t(s,r+a,o+c,r,o+c,d),t(s,r,o+c,r,o,d),t(s,r,o,r+a,o,l),s.closePath())}}var fh=(i,e,t)=>{i.moveTo(e,t)},ph=(i,e,t)=>{i.moveTo(t,e)},bo=(i,e,t)=>{i.lineTo(e,t)},So=(i,e,t)=>{i.lineTo(t,e)},mh=Fg(0),kd=Fg(1),Og=(i,e,t,n,s,r)=>{i.arc(e,t,n,s,r)},Bg=(i,e,t,n,s,r)=>{i.arc(t,e,n,s,r)},kg=(i,e,t,n,s,r,o)=>{i.bezierCurveTo(e,t,n,s,r,o)},zg=(i,e,t,n,s,r,o)=>{i.bezierCurveTo(t,e,s,n,o,r)};function Vg(i){return(e,t,n,s,r)=>_r(e,t,(o,a,c,l,d,u,h,m,g,v,p)=>{let{pxRound:f,points:y}=o,C,M;l.ori==0?(C=fh,M=Og):(C=ph,M=Bg);let R=Vt(y.width*Tt,3),b=(y.size-y.width)/2*Tt,_=Vt(b*2,3),A=new Path2D,H=new Path2D,{left:O,top:T,width:F,height:B}=e.bbox;mh(H,O-_,T-_,F+_*2,B+_*2);let D=V=>{if(c[V]!=null){let Y=f(u(a[V],l,v,m)),$=f(h(c[V],d,p,g));C(A,Y+b,$),M(A,Y,$,b,0,sh*2)}};if(r)r.forEach(D);else for(let V=n;V<=s;V++)D(V);return{stroke:R>0?A:null,fill:A,clip:H,flags:vo|Md}})}function Hg(i){return(e,t,n,s,r,o)=>{n!=s&&(r!=n&&o!=n&&i(e,t,n),r!=s&&o!=s&&i(e,t,s),i(e,t,o))}}var bw=Hg(bo),Sw=Hg(So);function Gg(i){let e=Mt(i?.alignGaps,0);return(t,n,s,r)=>_r(t,n,(o,a,c,l,d,u,h,m,g,v,p)=>{[s,r]=lh(c,s,r);let f=o.pxRound,y=B=>f(u(B,l,v,m)),C=B=>f(h(B,d,p,g)),M,R;l.ori==0?(M=bo,R=bw):(M=So,R=Sw);let b=l.dir*(l.ori==0?1:-1),_={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:vo},A=_.stroke,H=!1;if(r-s>=v*4){let B=he=>t.posToVal(he,l.key,!0),D=null,V=null,Y,$,ce,P=y(a[b==1?s:r]),I=y(a[s]),q=y(a[r]),ie=B(b==1?I+1:q-1);for(let he=b==1?s:r;he>=s&&he<=r;he+=b){let Q=a[he],le=(b==1?Q<ie:Q>ie)?P:y(Q),me=c[he];le==P?me!=null?($=me,D==null?(M(A,le,C($)),Y=D=V=$):$<D?D=$:$>V&&(V=$)):me===null&&(H=!0):(D!=null&&R(A,P,C(D),C(V),C(Y),C($)),me!=null?($=me,M(A,le,C($)),D=V=Y=$):(D=V=null,me===null&&(H=!0)),P=le,ie=B(P+b))}D!=null&&D!=V&&ce!=P&&R(A,P,C(D),C(V),C(Y),C($))}else for(let B=b==1?s:r;B>=s&&B<=r;B+=b){let D=c[B];D===null?H=!0:D!=null&&M(A,y(a[B]),C(D))}let[T,F]=Od(t,n);if(o.fill!=null||T!=0){let B=_.fill=new Path2D(A),D=o.fillTo(t,n,o.min,o.max,T),V=C(D),Y=y(a[s]),$=y(a[r]);b==-1&&([$,Y]=[Y,$]),M(B,$,V),M(B,Y,V)}if(!o.spanGaps){let B=[];H&&B.push(...Bd(a,c,s,r,b,y,e)),_.gaps=B=o.gaps(t,n,s,r,B),_.clip=dh(B,l.ori,m,g,v,p)}return F!=0&&(_.band=F==2?[ws(t,n,s,r,A,-1),ws(t,n,s,r,A,1)]:ws(t,n,s,r,A,F)),_})}function Mw(i){let e=Mt(i.align,1),t=Mt(i.ascDesc,!1),n=Mt(i.alignGaps,0),s=Mt(i.extend,!1);return(r,o,a,c)=>_r(r,o,(l,d,u,h,m,g,v,p,f,y,C)=>{[a,c]=lh(u,a,c);let M=l.pxRound,{left:R,width:b}=r.bbox,_=I=>M(g(I,h,y,p)),A=I=>M(v(I,m,C,f)),H=h.ori==0?bo:So,O={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:vo},T=O.stroke,F=h.dir*(h.ori==0?1:-1),B=A(u[F==1?a:c]),D=_(d[F==1?a:c]),V=D,Y=D;s&&e==-1&&(Y=R,H(T,Y,B)),H(T,D,B);for(let I=F==1?a:c;I>=a&&I<=c;I+=F){let q=u[I];if(q==null)continue;let ie=_(d[I]),he=A(q);e==1?H(T,ie,B):H(T,V,he),H(T,ie,he),B=he,V=ie}let $=V;s&&e==1&&($=R+b,H(T,$,B));let[ce,P]=Od(r,o);if(l.fill!=null||ce!=0){let I=O.fill=new Path2D(T),q=l.fillTo(r,o,l.min,l.max,ce),ie=A(q);H(I,$,ie),H(I,Y,ie)}if(!l.spanGaps){let I=[];I.push(...Bd(d,u,a,c,F,_,n));let q=l.width*Tt/2,ie=t||e==1?q:-q,he=t||e==-1?-q:q;I.forEach(Q=>{Q[0]+=ie,Q[1]+=he}),O.gaps=I=l.gaps(r,o,a,c,I),O.clip=dh(I,h.ori,p,f,y,C)}return P!=0&&(O.band=P==2?[ws(r,o,a,c,T,-1),ws(r,o,a,c,T,1)]:ws(r,o,a,c,T,P)),O})}function ig(i,e,t,n,s,r,o=zt){if(i.length>1){let a=null;for(let c=0,l=1/0;c<i.length;c++)if(e[c]!==void 0){if(a!=null){let d=vn(i[c]-i[a]);d<l&&(l=d,o=vn(t(i[c],n,s,r)-t(i[a],n,s,r)))}a=c}}return o}function ww(i){i=i||Ba;let e=Mt(i.size,[.6,zt,1]),t=i.align||0,n=i.gap||0,s=i.radius;s=s==null?[0,0]:typeof s=="number"?[s,0]:s;let r=xt(s),o=1-e[0],a=Mt(e[1],zt),c=Mt(e[2],1),l=Mt(i.disp,Ba),d=Mt(i.each,m=>{}),{fill:u,stroke:h}=l;return(m,g,v,p)=>_r(m,g,(f,y,C,M,R,b,_,A,H,O,T)=>{let F=f.pxRound,B=t,D=n*Tt,V=a*Tt,Y=c*Tt,$,ce;M.ori==0?[$,ce]=r(m,g):[ce,$]=r(m,g);let P=M.dir*(M.ori==0?1:-1),I=M.ori==0?mh:kd,q=M.ori==0?d:(Re,Je,at,Me,Bt,He,$e)=>{d(Re,Je,at,Bt,Me,$e,He)},ie=Mt(m.bands,Ld).find(Re=>Re.series[0]==g),he=ie!=null?ie.dir:0,Q=f.fillTo(m,g,f.min,f.max,he),fe=F(_(Q,R,T,H)),le,me,pe,De=O,Ze=F(f.width*Tt),Ne=!1,qe=null,ot=null,Qe=null,bt=null;u!=null&&(Ze==0||h!=null)&&(Ne=!0,qe=u.values(m,g,v,p),ot=new Map,new Set(qe).forEach(Re=>{Re!=null&&ot.set(Re,new Path2D)}),Ze>0&&(Qe=h.values(m,g,v,p),bt=new Map,new Set(Qe).forEach(Re=>{Re!=null&&bt.set(Re,new Path2D)})));let{x0:At,size:sn}=l;if(At!=null&&sn!=null){B=1,y=At.values(m,g,v,p),At.unit==2&&(y=y.map(at=>m.posToVal(A+at*O,M.key,!0)));let Re=sn.values(m,g,v,p);sn.unit==2?me=Re[0]*O:me=b(Re[0],M,O,A)-b(0,M,O,A),De=ig(y,C,b,M,O,A,De),pe=De-me+D}else De=ig(y,C,b,M,O,A,De),pe=De*o+D,me=De-pe;pe<1&&(pe=0),Ze>=me/2&&(Ze=0),pe<5&&(F=dg);let Nt=pe>0,yn=De-pe-(Nt?Ze:0);me=F(yd(yn,Y,V)),le=(B==0?me/2:B==P?0:me)-B*P*((B==0?D/2:0)+(Nt?Ze/2:0));let yt={stroke:null,fill:null,clip:null,band:null,gaps:null,flags:0},fn=Ne?null:new Path2D,Jt=null;if(ie!=null)Jt=m.data[ie.series[1]];else{let{y0:Re,y1:Je}=l;Re!=null&&Je!=null&&(C=Je.values(m,g,v,p),Jt=Re.values(m,g,v,p))}let rn=$*me,z=ce*me;for(let Re=P==1?v:p;Re>=v&&Re<=p;Re+=P){let Je=C[Re];if(Je==null)continue;if(Jt!=null){let Z=Jt[Re]??0;if(Je-Z==0)continue;fe=_(Z,R,T,H)}let at=M.distr!=2||l!=null?y[Re]:Re,Me=b(at,M,O,A),Bt=_(Mt(Je,Q),R,T,H),He=F(Me-le),$e=F(Jn(Bt,fe)),L=F(Bi(Bt,fe)),S=$e-L;if(Je!=null){let Z=Je<0?z:rn,de=Je<0?rn:z;Ne?(Ze>0&&Qe[Re]!=null&&I(bt.get(Qe[Re]),He,L+fi(Ze/2),me,Jn(0,S-Ze),Z,de),qe[Re]!=null&&I(ot.get(qe[Re]),He,L+fi(Ze/2),me,Jn(0,S-Ze),Z,de)):I(fn,He,L+fi(Ze/2),me,Jn(0,S-Ze),Z,de),q(m,g,Re,He-Ze/2,L,me+Ze,S)}}return Ze>0?yt.stroke=Ne?bt:fn:Ne||(yt._fill=f.width==0?f._fill:f._stroke??f._fill,yt.width=0),yt.fill=Ne?ot:fn,yt})}function Ew(i,e){let t=Mt(e?.alignGaps,0);return(n,s,r,o)=>_r(n,s,(a,c,l,d,u,h,m,g,v,p,f)=>{[r,o]=lh(l,r,o);let y=a.pxRound,C=$=>y(h($,d,p,g)),M=$=>y(m($,u,f,v)),R,b,_;d.ori==0?(R=fh,_=bo,b=kg):(R=ph,_=So,b=zg);let A=d.dir*(d.ori==0?1:-1),H=C(c[A==1?r:o]),O=H,T=[],F=[];for(let $=A==1?r:o;$>=r&&$<=o;$+=A)if(l[$]!=null){let P=c[$],I=C(P);T.push(O=I),F.push(M(l[$]))}let B={stroke:i(T,F,R,_,b,y),fill:null,clip:null,band:null,gaps:null,flags:vo},D=B.stroke,[V,Y]=Od(n,s);if(a.fill!=null||V!=0){let $=B.fill=new Path2D(D),ce=a.fillTo(n,s,a.min,a.max,V),P=M(ce);_($,O,P),_($,H,P)}if(!a.spanGaps){let $=[];$.push(...Bd(c,l,r,o,A,C,t)),B.gaps=$=a.gaps(n,s,r,o,$),B.clip=dh($,d.ori,g,v,p,f)}return Y!=0&&(B.band=Y==2?[ws(n,s,r,o,D,-1),ws(n,s,r,o,D,1)]:ws(n,s,r,o,D,Y)),B})}function Tw(i){return Ew(Aw,i)}function Aw(i,e,t,n,s,r){let o=i.length;if(o<2)return null;let a=new Path2D;if(t(a,i[0],e[0]),o==2)n(a,i[1],e[1]);else{let c=Array(o),l=Array(o-1),d=Array(o-1),u=Array(o-1);for(let h=0;h<o-1;h++)d[h]=e[h+1]-e[h],u[h]=i[h+1]-i[h],l[h]=d[h]/u[h];c[0]=l[0];for(let h=1;h<o-1;h++)l[h]===0||l[h-1]===0||l[h-1]>0!=l[h]>0?c[h]=0:(c[h]=3*(u[h-1]+u[h])/((2*u[h]+u[h-1])/l[h-1]+(u[h]+2*u[h-1])/l[h]),isFinite(c[h])||(c[h]=0));c[o-1]=l[o-2];for(let h=0;h<o-1;h++)s(a,i[h]+u[h]/3,e[h]+c[h]*u[h]/3,i[h+1]-u[h]/3,e[h+1]-c[h+1]*u[h]/3,i[h+1],e[h+1])}return a}var wd=new Set;function sg(){for(let i of wd)i.syncRect(!0)}yo&&(mr(aM,mo,sg),mr(lM,mo,sg,!0),mr(rh,mo,()=>{vt.pxRatio=Tt}));var Rw=Gg(),Cw=Vg();function rg(i,e,t,n){return(n?[i[0],i[1]].concat(i.slice(2)):[i[0]].concat(i.slice(1))).map((r,o)=>Ed(r,o,e,t))}function Pw(i,e){return i.map((t,n)=>n==0?{}:un({},e,t))}function Ed(i,e,t,n){return un({},e==0?t:n,i)}function Wg(i,e,t){return e==null?_o:[e,t]}var Iw=Wg;function Lw(i,e,t){return e==null?_o:oh(e,t,Pd,!0)}function $g(i,e,t,n){return e==null?_o:ch(e,t,i.scales[n].log,!1)}var Dw=$g;function Xg(i,e,t,n){return e==null?_o:Cd(e,t,i.scales[n].log,!1)}var Nw=Xg;function Uw(i,e,t,n,s){let r=Jn(Om(i),Om(e)),o=e-i,a=Oi(s/n*o,t);do{let c=t[a],l=n*c/o;if(l>=s&&r+(c<5?Ys.get(c):0)<=17)return[c,l]}while(++a<t.length);return[0,0]}function og(i){let e,t;return i=i.replace(/(\d+)px/,(n,s)=>(e=xn((t=+s)*Tt))+"px"),[i,e,t]}function Fw(i){i.show&&[i.font,i.labelFont].forEach(e=>{let t=Vt(e[2]*Tt,1);e[0]=e[0].replace(/[0-9.]+px/,t+"px"),e[1]=t})}function vt(i,e,t){let n={mode:Mt(i.mode,1)},s=n.mode;function r(x,w,N,U){let X=w.valToPct(x);return U+N*(w.dir==-1?1-X:X)}function o(x,w,N,U){let X=w.valToPct(x);return U+N*(w.dir==-1?X:1-X)}function a(x,w,N,U){return w.ori==0?r(x,w,N,U):o(x,w,N,U)}n.valToPosH=r,n.valToPosV=o;let c=!1;n.status=0;let l=n.root=bi(GS);if(i.id!=null&&(l.id=i.id),di(l,i.class),i.title){let x=bi(XS,l);x.textContent=i.title}let d=Fi("canvas"),u=n.ctx=d.getContext("2d"),h=bi(qS,l);mr("click",h,x=>{x.target===g&&(Gt!=wr||Yt!=Er)&&Rn.click(n,x)},!0);let m=n.under=bi(YS,h);h.appendChild(d);let g=n.over=bi(ZS,h);i=xo(i);let v=+Mt(i.pxAlign,1),p=ng(v);(i.plugins||[]).forEach(x=>{x.opts&&(i=x.opts(n,i)||i)});let f=i.ms||.001,y=n.series=s==1?rg(i.series||[],Zm,eg,!1):Pw(i.series||[null],Qm),C=n.axes=rg(i.axes||[],Ym,Km,!0),M=n.scales={},R=n.bands=i.bands||[];R.forEach(x=>{x.fill=xt(x.fill||null),x.dir=Mt(x.dir,-1)});let b=s==2?y[1].facets[0].scale:y[0].scale,_={axes:as,series:pt},A=(i.drawOrder||["axes","series"]).map(x=>_[x]);function H(x){let w=x.distr==3?N=>Ms(N>0?N:x.clamp(n,N,x.min,x.max,x.key)):x.distr==4?N=>dd(N,x.asinh):x.distr==100?N=>x.fwd(N):N=>N;return N=>{let U=w(N),{_min:X,_max:j}=x,ae=j-X;return(U-X)/ae}}function O(x){let w=M[x];if(w==null){let N=(i.scales||Ba)[x]||Ba;if(N.from!=null){O(N.from);let U=un({},M[N.from],N,{key:x});U.valToPct=H(U),M[x]=U}else{w=M[x]=un({},x==b?Ng:xw,N),w.key=x;let U=w.time,X=w.range,j=qs(X);if((x!=b||s==2&&!U)&&(j&&(X[0]==null||X[1]==null)&&(X={min:X[0]==null?Nm:{mode:1,hard:X[0],soft:X[0]},max:X[1]==null?Nm:{mode:1,hard:X[1],soft:X[1]}},j=!1),!j&&uh(X))){let ae=X;X=(ge,be,Ue)=>be==null?_o:oh(be,Ue,ae)}w.range=xt(X||(U?Iw:x==b?w.distr==3?Dw:w.distr==4?Nw:Wg:w.distr==3?$g:w.distr==4?Xg:Lw)),w.auto=xt(j?!1:w.auto),w.clamp=xt(w.clamp||_w),w._min=w._max=null,w.valToPct=H(w)}}}O("x"),O("y"),s==1&&y.forEach(x=>{O(x.scale)}),C.forEach(x=>{O(x.scale)});for(let x in i.scales)O(x);let T=M[b],F=T.distr,B,D;T.ori==0?(di(l,WS),B=r,D=o):(di(l,$S),B=o,D=r);let V={};for(let x in M){let w=M[x];(w.min!=null||w.max!=null)&&(V[x]={min:w.min,max:w.max},w.min=w.max=null)}let Y=i.tzDate||(x=>new Date(xn(x/f))),$=i.fmtDate||Dd,ce=f==1?WM(Y):qM(Y),P=$m(Y,Wm(f==1?GM:XM,$)),I=qm(Y,Xm(ZM,$)),q=[],ie=n.legend=un({},jM,i.legend),he=n.cursor=un({},sw,{drag:{y:s==2}},i.cursor),Q=ie.show,fe=he.show,le=ie.markers;ie.idxs=q,le.width=xt(le.width),le.dash=xt(le.dash),le.stroke=xt(le.stroke),le.fill=xt(le.fill);let me,pe,De,Ze=[],Ne=[],qe,ot=!1,Qe={};if(ie.live){let x=y[1]?y[1].values:null;ot=x!=null,qe=ot?x(n,1,0):{_:0};for(let w in qe)Qe[w]=Ad}if(Q)if(me=Fi("table",tM,l),De=Fi("tbody",null,me),ie.mount(n,me),ot){pe=Fi("thead",null,me,De);let x=Fi("tr",null,pe);Fi("th",null,x);for(var bt in qe)Fi("th",bm,x).textContent=bt}else di(me,iM),ie.live&&di(me,nM);let At={show:!0},sn={show:!1};function Nt(x,w){if(w==0&&(ot||!ie.live||s==2))return _o;let N=[],U=Fi("tr",sM,De,De.childNodes[w]);di(U,x.class),x.show||di(U,pr);let X=Fi("th",null,U);if(le.show){let ge=bi(rM,X);if(w>0){let be=le.width(n,w);be&&(ge.style.border=be+"px "+le.dash(n,w)+" "+le.stroke(n,w)),ge.style.background=le.fill(n,w)}}let j=bi(bm,X);x.label instanceof HTMLElement?j.appendChild(x.label):j.textContent=x.label,w>0&&(le.show||(j.style.color=x.width>0?le.stroke(n,w):le.fill(n,w)),yt("click",X,ge=>{if(he._lock)return;et(ge);let be=y.indexOf(x);if((ge.ctrlKey||ge.metaKey)!=ie.isolate){let Ue=y.some((Fe,Be)=>Be>0&&Be!=be&&Fe.show);y.forEach((Fe,Be)=>{Be>0&&Hi(Be,Ue?Be==be?At:sn:At,!0,cn.setSeries)})}else Hi(be,{show:!x.show},!0,cn.setSeries)},!1),tt&&yt(Em,X,ge=>{he._lock||(et(ge),Hi(y.indexOf(x),Ar,!0,cn.setSeries))},!1));for(var ae in qe){let ge=Fi("td",oM,U);ge.textContent="--",N.push(ge)}return[U,N]}let yn=new Map;function yt(x,w,N,U=!0){let X=yn.get(w)||{},j=he.bind[x](n,w,N,U);j&&(mr(x,w,X[x]=j),yn.set(w,X))}function fn(x,w,N){let U=yn.get(w)||{};for(let X in U)(x==null||X==x)&&(vd(X,w,U[X]),delete U[X]);x==null&&yn.delete(w)}let Jt=0,rn=0,z=0,Re=0,Je=0,at=0,Me=Je,Bt=at,He=z,$e=Re,L=0,S=0,Z=0,de=0;n.bbox={};let oe=!1,ve=!1,ye=!1,te=!1,se=!1,_e=!1;function k(x,w,N){(N||x!=n.width||w!=n.height)&&re(x,w),ut(!1),ye=!0,ve=!0,Nn()}function re(x,w){n.width=Jt=z=x,n.height=rn=Re=w,Je=at=0,Se(),Ge();let N=n.bbox;L=N.left=dr(Je*Tt,.5),S=N.top=dr(at*Tt,.5),Z=N.width=dr(z*Tt,.5),de=N.height=dr(Re*Tt,.5)}let ne=3;function we(){let x=!1,w=0;for(;!x;){w++;let N=br(w),U=Vi(w);x=w==ne||N&&U,x||(re(n.width,n.height),ve=!0)}}function xe({width:x,height:w}){k(x,w)}n.setSize=xe;function Se(){let x=!1,w=!1,N=!1,U=!1;C.forEach((X,j)=>{if(X.show&&X._show){let{side:ae,_size:ge}=X,be=ae%2,Ue=X.label!=null?X.labelSize:0,Fe=ge+Ue;Fe>0&&(be?(z-=Fe,ae==3?(Je+=Fe,U=!0):N=!0):(Re-=Fe,ae==0?(at+=Fe,x=!0):w=!0))}}),ki[0]=x,ki[1]=N,ki[2]=w,ki[3]=U,z-=Mi[1]+Mi[3],Je+=Mi[3],Re-=Mi[2]+Mi[0],at+=Mi[0]}function Ge(){let x=Je+z,w=at+Re,N=Je,U=at;function X(j,ae){switch(j){case 1:return x+=ae,x-ae;case 2:return w+=ae,w-ae;case 3:return N-=ae,N+ae;case 0:return U-=ae,U+ae}}C.forEach((j,ae)=>{if(j.show&&j._show){let ge=j.side;j._pos=X(ge,j._size),j.label!=null&&(j._lpos=X(ge,j.labelSize))}})}if(he.dataIdx==null){let x=he.hover,w=x.skip=new Set(x.skip??[]);w.add(void 0);let N=x.prox=xt(x.prox),U=x.bias??(x.bias=0);he.dataIdx=(X,j,ae,ge)=>{if(j==0)return ae;let be=ae,Ue=N(X,j,ae,ge)??zt,Fe=Ue>=0&&Ue<zt,Be=T.ori==0?z:Re,rt=he.left,wt=e[0],St=e[j];if(w.has(St[ae])){be=null;let mt=null,Ke=null,We;if(U==0||U==-1)for(We=ae;mt==null&&We-- >0;)w.has(St[We])||(mt=We);if(U==0||U==1)for(We=ae;Ke==null&&We++<St.length;)w.has(St[We])||(Ke=We);if(mt!=null||Ke!=null)if(Fe){let $t=mt==null?-1/0:B(wt[mt],T,Be,0),Qt=Ke==null?1/0:B(wt[Ke],T,Be,0),wn=rt-$t,Ut=Qt-rt;wn<=Ut?wn<=Ue&&(be=mt):Ut<=Ue&&(be=Ke)}else be=Ke==null?mt:mt==null?Ke:ae-mt<=Ke-ae?mt:Ke}else Fe&&vn(rt-B(wt[ae],T,Be,0))>Ue&&(be=null);return be}}let et=x=>{he.event=x};he.idxs=q,he._lock=!1;let ue=he.points;ue.show=xt(ue.show),ue.size=xt(ue.size),ue.stroke=xt(ue.stroke),ue.width=xt(ue.width),ue.fill=xt(ue.fill);let ke=n.focus=un({},i.focus||{alpha:.3},he.focus),tt=ke.prox>=0,Ae=tt&&ue.one,ht=[],Ht=[],kn=[];function Ao(x,w){let N=ue.show(n,w);if(N instanceof HTMLElement)return di(N,eM),di(N,x.class),ts(N,-10,-10,z,Re),g.insertBefore(N,ht[w]),N}function xr(x,w){if(s==1||w>0){let N=s==1&&M[x.scale].time,U=x.value;x.value=N?zm(U)?qm(Y,Xm(U,$)):U||I:U||pw,x.label=x.label||(N?ow:rw)}if(Ae||w>0){x.width=x.width==null?1:x.width,x.paths=x.paths||Rw||xM,x.fillTo=xt(x.fillTo||vw),x.pxAlign=+Mt(x.pxAlign,v),x.pxRound=ng(x.pxAlign),x.stroke=xt(x.stroke||null),x.fill=xt(x.fill||null),x._stroke=x._fill=x._paths=x._focus=null;let N=mw(Jn(1,x.width),1),U=x.points=un({},{size:N,width:Jn(1,N*.2),stroke:x.stroke,space:N*2,paths:Cw,_stroke:null,_fill:null},x.points);U.show=xt(U.show),U.filter=xt(U.filter),U.fill=xt(U.fill),U.stroke=xt(U.stroke),U.paths=xt(U.paths),U.pxAlign=x.pxAlign}if(Q){let N=Nt(x,w);Ze.splice(w,0,N[0]),Ne.splice(w,0,N[1]),ie.values.push(null)}if(fe){q.splice(w,0,null);let N=null;Ae?w==0&&(N=Ao(x,w)):w>0&&(N=Ao(x,w)),ht.splice(w,0,N),Ht.splice(w,0,0),kn.splice(w,0,0)}Mn("addSeries",w)}function Sh(x,w){w=w??y.length,x=s==1?Ed(x,w,Zm,eg):Ed(x,w,{},Qm),y.splice(w,0,x),xr(y[w],w)}n.addSeries=Sh;function Ha(x){if(y.splice(x,1),Q){ie.values.splice(x,1),Ne.splice(x,1);let w=Ze.splice(x,1)[0];fn(null,w.firstChild),w.remove()}fe&&(q.splice(x,1),ht.splice(x,1)[0].remove(),Ht.splice(x,1),kn.splice(x,1)),Mn("delSeries",x)}n.delSeries=Ha;let ki=[!1,!1,!1,!1];function ss(x,w){if(x._show=x.show,x.show){let N=x.side%2,U=M[x.scale];U==null&&(x.scale=N?y[1].scale:b,U=M[x.scale]);let X=U.time;x.size=xt(x.size),x.space=xt(x.space),x.rotate=xt(x.rotate),qs(x.incrs)&&x.incrs.forEach(ae=>{!Ys.has(ae)&&Ys.set(ae,mg(ae))}),x.incrs=xt(x.incrs||(U.distr==2?zM:X?f==1?HM:$M:fr)),x.splits=xt(x.splits||(X&&U.distr==1?ce:U.distr==3?bd:U.distr==4?cw:lw)),x.stroke=xt(x.stroke),x.grid.stroke=xt(x.grid.stroke),x.ticks.stroke=xt(x.ticks.stroke),x.border.stroke=xt(x.border.stroke);let j=x.values;x.values=qs(j)&&!qs(j[0])?xt(j):X?qs(j)?$m(Y,Wm(j,$)):zm(j)?YM(Y,j):j||P:j||aw,x.filter=xt(x.filter||(U.distr>=3&&U.log==10?dw:U.distr==3&&U.log==2?fw:fg)),x.font=og(x.font),x.labelFont=og(x.labelFont),x._size=x.size(n,null,w,0),x._space=x._rotate=x._incrs=x._found=x._splits=x._values=null,x._size>0&&(ki[w]=!0,x._el=bi(JS,h))}}function rs(x,w,N,U){let[X,j,ae,ge]=N,be=w%2,Ue=0;return be==0&&(ge||j)&&(Ue=w==0&&!X||w==2&&!ae?xn(Ym.size/3):0),be==1&&(X||ae)&&(Ue=w==1&&!j||w==3&&!ge?xn(Km.size/2):0),Ue}let Ro=n.padding=(i.padding||[rs,rs,rs,rs]).map(x=>xt(Mt(x,rs))),Mi=n._padding=Ro.map((x,w)=>x(n,w,ki,0)),Kt,tn=null,nn=null,zi=s==1?y[0].idxs:null,ti=null,Es=!1;function Co(x,w){if(e=x??[],n.data=n._data=e,s==2){Kt=0;for(let N=1;N<y.length;N++)Kt+=e[N][0].length}else{e.length==0&&(n.data=n._data=e=[[]]),ti=e[0],Kt=ti.length;let N=e;if(F==2){N=e.slice();let U=N[0]=Array(Kt);for(let X=0;X<Kt;X++)U[X]=X}n._data=e=N}if(ut(!0),Mn("setData"),F==2&&(ye=!0),w!==!1){let N=T;N.auto(n,Es)?Po():Rs(b,N.min,N.max),te=te||he.left>=0,_e=!0,Nn()}}n.setData=Co;function Po(){Es=!0;let x,w;s==1&&(Kt>0?(tn=zi[0]=0,nn=zi[1]=Kt-1,x=e[0][tn],w=e[0][nn],F==2?(x=tn,w=nn):x==w&&(F==3?[x,w]=ch(x,x,T.log,!1):F==4?[x,w]=Cd(x,x,T.log,!1):T.time?w=x+xn(86400/f):[x,w]=oh(x,w,Pd,!0))):(tn=zi[0]=x=null,nn=zi[1]=w=null)),Rs(b,x,w)}let vr,Ts,yr,E,G,ee,J,K,Ee,Pe;function Te(x,w,N,U,X,j){x??(x=Mm),N??(N=Ld),U??(U="butt"),X??(X=Mm),j??(j="round"),x!=vr&&(u.strokeStyle=vr=x),X!=Ts&&(u.fillStyle=Ts=X),w!=yr&&(u.lineWidth=yr=w),j!=G&&(u.lineJoin=G=j),U!=ee&&(u.lineCap=ee=U),N!=E&&u.setLineDash(E=N)}function Ie(x,w,N,U){w!=Ts&&(u.fillStyle=Ts=w),x!=J&&(u.font=J=x),N!=K&&(u.textAlign=K=N),U!=Ee&&(u.textBaseline=Ee=U)}function Ve(x,w,N,U,X=0){if(U.length>0&&x.auto(n,Es)&&(w==null||w.min==null)){let j=Mt(tn,0),ae=Mt(nn,U.length-1),ge=N.min==null?dM(U,j,ae,X,x.distr==3):[N.min,N.max];x.min=Bi(x.min,N.min=ge[0]),x.max=Jn(x.max,N.max=ge[1])}}let nt={min:null,max:null};function ft(){for(let U in M){let X=M[U];V[U]==null&&(X.min==null||V[b]!=null&&X.auto(n,Es))&&(V[U]=nt)}for(let U in M){let X=M[U];V[U]==null&&X.from!=null&&V[X.from]!=null&&(V[U]=nt)}V[b]!=null&&ut(!0);let x={};for(let U in V){let X=V[U];if(X!=null){let j=x[U]=xo(M[U],bM);if(X.min!=null)un(j,X);else if(U!=b||s==2)if(Kt==0&&j.from==null){let ae=j.range(n,null,null,U);j.min=ae[0],j.max=ae[1]}else j.min=zt,j.max=-zt}}if(Kt>0){y.forEach((U,X)=>{if(s==1){let j=U.scale,ae=V[j];if(ae==null)return;let ge=x[j];if(X==0){let be=ge.range(n,ge.min,ge.max,j);ge.min=be[0],ge.max=be[1],tn=Oi(ge.min,e[0]),nn=Oi(ge.max,e[0]),nn-tn>1&&(e[0][tn]<ge.min&&tn++,e[0][nn]>ge.max&&nn--),U.min=ti[tn],U.max=ti[nn]}else U.show&&U.auto&&Ve(ge,ae,U,e[X],U.sorted);U.idxs[0]=tn,U.idxs[1]=nn}else if(X>0&&U.show&&U.auto){let[j,ae]=U.facets,ge=j.scale,be=ae.scale,[Ue,Fe]=e[X],Be=x[ge],rt=x[be];Be!=null&&Ve(Be,V[ge],j,Ue,j.sorted),rt!=null&&Ve(rt,V[be],ae,Fe,ae.sorted),U.min=ae.min,U.max=ae.max}});for(let U in x){let X=x[U],j=V[U];if(X.from==null&&(j==null||j.min==null)){let ae=X.range(n,X.min==zt?null:X.min,X.max==-zt?null:X.max,U);X.min=ae[0],X.max=ae[1]}}}for(let U in x){let X=x[U];if(X.from!=null){let j=x[X.from];if(j.min==null)X.min=X.max=null;else{let ae=X.range(n,j.min,j.max,U);X.min=ae[0],X.max=ae[1]}}}let w={},N=!1;for(let U in x){let X=x[U],j=M[U];if(j.min!=X.min||j.max!=X.max){j.min=X.min,j.max=X.max;let ae=j.distr;j._min=ae==3?Ms(j.min):ae==4?dd(j.min,j.asinh):ae==100?j.fwd(j.min):j.min,j._max=ae==3?Ms(j.max):ae==4?dd(j.max,j.asinh):ae==100?j.fwd(j.max):j.max,w[U]=N=!0}}if(N){y.forEach((U,X)=>{s==2?X>0&&w.y&&(U._paths=null):w[U.scale]&&(U._paths=null)});for(let U in w)ye=!0,Mn("setScale",U);fe&&he.left>=0&&(te=_e=!0)}for(let U in V)V[U]=null}function ze(x){let w=yd(tn-1,0,Kt-1),N=yd(nn+1,0,Kt-1);for(;x[w]==null&&w>0;)w--;for(;x[N]==null&&N<Kt-1;)N++;return[w,N]}function pt(){if(Kt>0){let x=y.some(w=>w._focus)&&Pe!=ke.alpha;x&&(u.globalAlpha=Pe=ke.alpha),y.forEach((w,N)=>{if(N>0&&w.show&&(Zt(N,!1),Zt(N,!0),w._paths==null)){let U=Pe;Pe!=w.alpha&&(u.globalAlpha=Pe=w.alpha);let X=s==2?[0,e[N][0].length-1]:ze(e[N]);w._paths=w.paths(n,N,X[0],X[1]),Pe!=U&&(u.globalAlpha=Pe=U)}}),y.forEach((w,N)=>{if(N>0&&w.show){let U=Pe;Pe!=w.alpha&&(u.globalAlpha=Pe=w.alpha),w._paths!=null&&It(N,!1);{let X=w._paths!=null?w._paths.gaps:null,j=w.points.show(n,N,tn,nn,X),ae=w.points.filter(n,N,j,X);(j||ae)&&(w.points._paths=w.points.paths(n,N,tn,nn,ae),It(N,!0))}Pe!=U&&(u.globalAlpha=Pe=U),Mn("drawSeries",N)}}),x&&(u.globalAlpha=Pe=1)}}function Zt(x,w){let N=w?y[x].points:y[x];N._stroke=N.stroke(n,x),N._fill=N.fill(n,x)}function It(x,w){let N=w?y[x].points:y[x],{stroke:U,fill:X,clip:j,flags:ae,_stroke:ge=N._stroke,_fill:be=N._fill,_width:Ue=N.width}=N._paths;Ue=Vt(Ue*Tt,3);let Fe=null,Be=Ue%2/2;w&&be==null&&(be=Ue>0?"#fff":ge);let rt=N.pxAlign==1&&Be>0;if(rt&&u.translate(Be,Be),!w){let wt=L-Ue/2,St=S-Ue/2,mt=Z+Ue,Ke=de+Ue;Fe=new Path2D,Fe.rect(wt,St,mt,Ke)}w?Oe(ge,Ue,N.dash,N.cap,be,U,X,ae,j):Lt(x,ge,Ue,N.dash,N.cap,be,U,X,ae,Fe,j),rt&&u.translate(-Be,-Be)}function Lt(x,w,N,U,X,j,ae,ge,be,Ue,Fe){let Be=!1;be!=0&&R.forEach((rt,wt)=>{if(rt.series[0]==x){let St=y[rt.series[1]],mt=e[rt.series[1]],Ke=(St._paths||Ba).band;qs(Ke)&&(Ke=rt.dir==1?Ke[0]:Ke[1]);let We,$t=null;St.show&&Ke&&pM(mt,tn,nn)?($t=rt.fill(n,wt)||j,We=St._paths.clip):Ke=null,Oe(w,N,U,X,$t,ae,ge,be,Ue,Fe,We,Ke),Be=!0}}),Be||Oe(w,N,U,X,j,ae,ge,be,Ue,Fe)}let pn=vo|Md;function Oe(x,w,N,U,X,j,ae,ge,be,Ue,Fe,Be){Te(x,w,N,U,X),(be||Ue||Be)&&(u.save(),be&&u.clip(be),Ue&&u.clip(Ue)),Be?(ge&pn)==pn?(u.clip(Be),Fe&&u.clip(Fe),gt(X,ae),on(x,j,w)):ge&Md?(gt(X,ae),u.clip(Be),on(x,j,w)):ge&vo&&(u.save(),u.clip(Be),Fe&&u.clip(Fe),gt(X,ae),u.restore(),on(x,j,w)):(gt(X,ae),on(x,j,w)),(be||Ue||Be)&&u.restore()}function on(x,w,N){N>0&&(w instanceof Map?w.forEach((U,X)=>{u.strokeStyle=vr=X,u.stroke(U)}):w!=null&&x&&u.stroke(w))}function gt(x,w){w instanceof Map?w.forEach((N,U)=>{u.fillStyle=Ts=U,u.fill(N)}):w!=null&&x&&u.fill(w)}function os(x,w,N,U){let X=C[x],j;if(U<=0)j=[0,0];else{let ae=X._space=X.space(n,x,w,N,U),ge=X._incrs=X.incrs(n,x,w,N,U,ae);j=Uw(w,N,ge,U,ae)}return X._found=j}function an(x,w,N,U,X,j,ae,ge,be,Ue){let Fe=ae%2/2;v==1&&u.translate(Fe,Fe),Te(ge,ae,be,Ue,ge),u.beginPath();let Be,rt,wt,St,mt=X+(U==0||U==3?-j:j);N==0?(rt=X,St=mt):(Be=X,wt=mt);for(let Ke=0;Ke<x.length;Ke++)w[Ke]!=null&&(N==0?Be=wt=x[Ke]:rt=St=x[Ke],u.moveTo(Be,rt),u.lineTo(wt,St));u.stroke(),v==1&&u.translate(-Fe,-Fe)}function br(x){let w=!0;return C.forEach((N,U)=>{if(!N.show)return;let X=M[N.scale];if(X.min==null){N._show&&(w=!1,N._show=!1,ut(!1));return}else N._show||(w=!1,N._show=!0,ut(!1));let j=N.side,ae=j%2,{min:ge,max:be}=X,[Ue,Fe]=os(U,ge,be,ae==0?z:Re);if(Fe==0)return;let Be=X.distr==2,rt=N._splits=N.splits(n,U,ge,be,Ue,Fe,Be),wt=X.distr==2?rt.map(We=>ti[We]):rt,St=X.distr==2?ti[rt[1]]-ti[rt[0]]:Ue,mt=N._values=N.values(n,N.filter(n,wt,U,Fe,St),U,Fe,St);N._rotate=j==2?N.rotate(n,mt,U,Fe):0;let Ke=N._size;N._size=Si(N.size(n,mt,U,x)),Ke!=null&&N._size!=Ke&&(w=!1)}),w}function Vi(x){let w=!0;return Ro.forEach((N,U)=>{let X=N(n,U,ki,x);X!=Mi[U]&&(w=!1),Mi[U]=X}),w}function as(){for(let x=0;x<C.length;x++){let w=C[x];if(!w.show||!w._show)continue;let N=w.side,U=N%2,X,j,ae=w.stroke(n,x),ge=N==0||N==3?-1:1,[be,Ue]=w._found;if(w.label!=null){let Hn=w.labelGap*ge,si=xn((w._lpos+Hn)*Tt);Ie(w.labelFont[0],ae,"center",N==2?"top":Sm),u.save(),U==1?(X=j=0,u.translate(si,xn(S+de/2)),u.rotate((N==3?-sh:sh)/2)):(X=xn(L+Z/2),j=si);let Ks=ug(w.label)?w.label(n,x,be,Ue):w.label;u.fillText(Ks,X,j),u.restore()}if(Ue==0)continue;let Fe=M[w.scale],Be=U==0?Z:de,rt=U==0?L:S,wt=w._splits,St=Fe.distr==2?wt.map(Hn=>ti[Hn]):wt,mt=Fe.distr==2?ti[wt[1]]-ti[wt[0]]:be,Ke=w.ticks,We=w.border,$t=Ke.show?Ke.size:0,Qt=xn($t*Tt),wn=xn((w.alignTo==2?w._size-$t-w.gap:w.gap)*Tt),Ut=w._rotate*-sh/180,en=p(w._pos*Tt),ni=(Qt+wn)*ge,Vn=en+ni;j=U==0?Vn:0,X=U==1?Vn:0;let gi=w.font[0],wi=w.align==1?fo:w.align==2?cd:Ut>0?fo:Ut<0?cd:U==0?"center":N==3?cd:fo,Wi=Ut||U==1?"middle":N==2?"top":Sm;Ie(gi,ae,wi,Wi);let ii=w.font[1]*w.lineGap,_i=wt.map(Hn=>p(a(Hn,Fe,Be,rt))),Ei=w._values;for(let Hn=0;Hn<Ei.length;Hn++){let si=Ei[Hn];if(si!=null){U==0?X=_i[Hn]:j=_i[Hn],si=""+si;let Ks=si.indexOf(`
`)==-1?[si]:si.split(/\n/gm);for(let Gn=0;Gn<Ks.length;Gn++){let pf=Ks[Gn];Ut?(u.save(),u.translate(X,j+Gn*ii),u.rotate(Ut),u.fillText(pf,0,0),u.restore()):u.fillText(pf,X,j+Gn*ii)}}}Ke.show&&an(_i,Ke.filter(n,St,x,Ue,mt),U,N,en,Qt,Vt(Ke.width*Tt,3),Ke.stroke(n,x),Ke.dash,Ke.cap);let $i=w.grid;$i.show&&an(_i,$i.filter(n,St,x,Ue,mt),U,U==0?2:1,U==0?S:L,U==0?de:Z,Vt($i.width*Tt,3),$i.stroke(n,x),$i.dash,$i.cap),We.show&&an([en],[1],U==0?1:0,U==0?1:2,U==1?S:L,U==1?de:Z,Vt(We.width*Tt,3),We.stroke(n,x),We.dash,We.cap)}Mn("drawAxes")}function ut(x){y.forEach((w,N)=>{N>0&&(w._paths=null,x&&(s==1?(w.min=null,w.max=null):w.facets.forEach(U=>{U.min=null,U.max=null})))})}let jt=!1,zn=!1,Dt=[];function ln(){zn=!1;for(let x=0;x<Dt.length;x++)Mn(...Dt[x]);Dt.length=0}function Nn(){jt||(RM(Zd),jt=!0)}function Ga(x,w=!1){jt=!0,zn=w,x(n),Zd(),w&&Dt.length>0&&queueMicrotask(ln)}n.batch=Ga;function Zd(){if(oe&&(ft(),oe=!1),ye&&(we(),ye=!1),ve){if(qt(m,fo,Je),qt(m,"top",at),qt(m,Na,z),qt(m,Ua,Re),qt(g,fo,Je),qt(g,"top",at),qt(g,Na,z),qt(g,Ua,Re),qt(h,Na,Jt),qt(h,Ua,rn),d.width=xn(Jt*Tt),d.height=xn(rn*Tt),C.forEach(({_el:x,_show:w,_size:N,_pos:U,side:X})=>{if(x!=null)if(w){let j=X===3||X===0?N:0,ae=X%2==1;qt(x,ae?"left":"top",U-j),qt(x,ae?"width":"height",N),qt(x,ae?"top":"left",ae?at:Je),qt(x,ae?"height":"width",ae?Re:z),xd(x,pr)}else di(x,pr)}),vr=Ts=yr=G=ee=J=K=Ee=E=null,Pe=1,Do(!0),Je!=Me||at!=Bt||z!=He||Re!=$e){ut(!1);let x=z/He,w=Re/$e;if(fe&&!te&&he.left>=0){he.left*=x,he.top*=w,Sr&&ts(Sr,xn(he.left),0,z,Re),Mr&&ts(Mr,0,xn(he.top),z,Re);for(let N=0;N<ht.length;N++){let U=ht[N];U!=null&&(Ht[N]*=x,kn[N]*=w,ts(U,Si(Ht[N]),Si(kn[N]),z,Re))}}if(Wt.show&&!se&&Wt.left>=0&&Wt.width>0){Wt.left*=x,Wt.width*=x,Wt.top*=w,Wt.height*=w;for(let N in Rh)qt(Tr,N,Wt[N])}Me=Je,Bt=at,He=z,$e=Re}Mn("setSize"),ve=!1}Jt>0&&rn>0&&(u.clearRect(0,0,d.width,d.height),Mn("drawClear"),A.forEach(x=>x()),Mn("draw")),Wt.show&&se&&(Wa(Wt),se=!1),fe&&te&&(Js(null,!0,!1),te=!1),ie.show&&ie.live&&_e&&(Th(),_e=!1),c||(c=!0,n.status=1,Mn("ready")),Es=!1,jt=!1}n.redraw=(x,w)=>{ye=w||!1,x!==!1?Rs(b,T.min,T.max):Nn()};function Mh(x,w){let N=M[x];if(N.from==null){if(Kt==0){let U=N.range(n,w.min,w.max,x);w.min=U[0],w.max=U[1]}if(w.min>w.max){let U=w.min;w.min=w.max,w.max=U}if(Kt>1&&w.min!=null&&w.max!=null&&w.max-w.min<1e-16)return;x==b&&N.distr==2&&Kt>0&&(w.min=Oi(w.min,e[0]),w.max=Oi(w.max,e[0]),w.min==w.max&&w.max++),V[x]=w,oe=!0,Nn()}}n.setScale=Mh;let wh,Eh,Sr,Mr,Jd,Kd,wr,Er,jd,Qd,Gt,Yt,As=!1,Rn=he.drag,bn=Rn.x,Sn=Rn.y;fe&&(he.x&&(wh=bi(jS,g)),he.y&&(Eh=bi(QS,g)),T.ori==0?(Sr=wh,Mr=Eh):(Sr=Eh,Mr=wh),Gt=he.left,Yt=he.top);let Wt=n.select=un({show:!0,over:!0,left:0,width:0,top:0,height:0},i.select),Tr=Wt.show?bi(KS,Wt.over?g:m):null;function Wa(x,w){if(Wt.show){for(let N in x)Wt[N]=x[N],N in Rh&&qt(Tr,N,x[N]);w!==!1&&Mn("setSelect")}}n.setSelect=Wa;function b0(x){if(y[x].show)Q&&xd(Ze[x],pr);else if(Q&&di(Ze[x],pr),fe){let N=Ae?ht[0]:ht[x];N!=null&&ts(N,-10,-10,z,Re)}}function Rs(x,w,N){Mh(x,{min:w,max:N})}function Hi(x,w,N,U){w.focus!=null&&T0(x),w.show!=null&&y.forEach((X,j)=>{j>0&&(x==j||x==null)&&(X.show=w.show,b0(j),s==2?(Rs(X.facets[0].scale,null,null),Rs(X.facets[1].scale,null,null)):Rs(X.scale,null,null),Nn())}),N!==!1&&Mn("setSeries",x,w),U&&No("setSeries",n,x,w)}n.setSeries=Hi;function S0(x,w){un(R[x],w)}function M0(x,w){x.fill=xt(x.fill||null),x.dir=Mt(x.dir,-1),w=w??R.length,R.splice(w,0,x)}function w0(x){x==null?R.length=0:R.splice(x,1)}n.addBand=M0,n.setBand=S0,n.delBand=w0;function E0(x,w){y[x].alpha=w,fe&&ht[x]!=null&&(ht[x].style.opacity=w),Q&&Ze[x]&&(Ze[x].style.opacity=w)}let ls,Cs,Zs,Ar={focus:!0};function T0(x){if(x!=Zs){let w=x==null,N=ke.alpha!=1;y.forEach((U,X)=>{if(s==1||X>0){let j=w||X==0||X==x;U._focus=w?null:j,N&&E0(X,j?1:ke.alpha)}}),Zs=x,N&&Nn()}}Q&&tt&&yt(Tm,me,x=>{he._lock||(et(x),Zs!=null&&Hi(null,Ar,!0,cn.setSeries))});function Gi(x,w,N){let U=M[w];N&&(x=x/Tt-(U.ori==1?at:Je));let X=z;U.ori==1&&(X=Re,x=X-x),U.dir==-1&&(x=X-x);let j=U._min,ae=U._max,ge=x/X,be=j+(ae-j)*ge,Ue=U.distr;return Ue==3?go(10,be):Ue==4?gM(be,U.asinh):Ue==100?U.bwd(be):be}function A0(x,w){let N=Gi(x,b,w);return Oi(N,e[0],tn,nn)}n.valToIdx=x=>Oi(x,e[0]),n.posToIdx=A0,n.posToVal=Gi,n.valToPos=(x,w,N)=>M[w].ori==0?r(x,M[w],N?Z:z,N?L:0):o(x,M[w],N?de:Re,N?S:0),n.setCursor=(x,w,N)=>{Gt=x.left,Yt=x.top,Js(null,w,N)};function ef(x,w){qt(Tr,fo,Wt.left=x),qt(Tr,Na,Wt.width=w)}function tf(x,w){qt(Tr,"top",Wt.top=x),qt(Tr,Ua,Wt.height=w)}let Io=T.ori==0?ef:tf,Lo=T.ori==1?ef:tf;function R0(){if(Q&&ie.live)for(let x=s==2?1:0;x<y.length;x++){if(x==0&&ot)continue;let w=ie.values[x],N=0;for(let U in w)Ne[x][N++].firstChild.nodeValue=w[U]}}function Th(x,w){if(x!=null&&(x.idxs?x.idxs.forEach((N,U)=>{q[U]=N}):yM(x.idx)||q.fill(x.idx),ie.idx=q[0]),Q&&ie.live){for(let N=0;N<y.length;N++)(N>0||s==1&&!ot)&&C0(N,q[N]);R0()}_e=!1,w!==!1&&Mn("setLegend")}n.setLegend=Th;function C0(x,w){let N=y[x],U=x==0&&F==2?ti:e[x],X;ot?X=N.values(n,x,w)??Qe:(X=N.value(n,w==null?null:U[w],x,w),X=X==null?Qe:{_:X}),ie.values[x]=X}function Js(x,w,N){jd=Gt,Qd=Yt,[Gt,Yt]=he.move(n,Gt,Yt),he.left=Gt,he.top=Yt,fe&&(Sr&&ts(Sr,xn(Gt),0,z,Re),Mr&&ts(Mr,0,xn(Yt),z,Re));let U,X=tn>nn;ls=zt,Cs=null;let j=T.ori==0?z:Re,ae=T.ori==1?z:Re;if(Gt<0||Kt==0||X){U=he.idx=null;for(let ge=0;ge<y.length;ge++){let be=ht[ge];be!=null&&ts(be,-10,-10,z,Re)}tt&&Hi(null,Ar,!0,x==null&&cn.setSeries),ie.live&&(q.fill(U),_e=!0)}else{let ge,be,Ue;s==1&&(ge=T.ori==0?Gt:Yt,be=Gi(ge,b),U=he.idx=Oi(be,e[0],tn,nn),Ue=B(e[0][U],T,j,0));let Fe=-10,Be=-10,rt=0,wt=0,St=!0,mt="",Ke="";for(let We=s==2?1:0;We<y.length;We++){let $t=y[We],Qt=q[We],wn=Qt==null?null:s==1?e[We][Qt]:e[We][1][Qt],Ut=he.dataIdx(n,We,U,be),en=Ut==null?null:s==1?e[We][Ut]:e[We][1][Ut];if(_e=_e||en!=wn||Ut!=Qt,q[We]=Ut,We>0&&$t.show){let ni=Ut==null?-10:Ut==U?Ue:B(s==1?e[0][Ut]:e[We][0][Ut],T,j,0),Vn=en==null?-10:D(en,s==1?M[$t.scale]:M[$t.facets[1].scale],ae,0);if(tt&&en!=null){let gi=T.ori==1?Gt:Yt,wi=vn(ke.dist(n,We,Ut,Vn,gi));if(wi<ls){let Wi=ke.bias;if(Wi!=0){let ii=Gi(gi,$t.scale),_i=en>=0?1:-1,Ei=ii>=0?1:-1;Ei==_i&&(Ei==1?Wi==1?en>=ii:en<=ii:Wi==1?en<=ii:en>=ii)&&(ls=wi,Cs=We)}else ls=wi,Cs=We}}if(_e||Ae){let gi,wi;T.ori==0?(gi=ni,wi=Vn):(gi=Vn,wi=ni);let Wi,ii,_i,Ei,$i,Hn,si=!0,Ks=ue.bbox;if(Ks!=null){si=!1;let Gn=Ks(n,We);_i=Gn.left,Ei=Gn.top,Wi=Gn.width,ii=Gn.height}else _i=gi,Ei=wi,Wi=ii=ue.size(n,We);if(Hn=ue.fill(n,We),$i=ue.stroke(n,We),Ae)We==Cs&&ls<=ke.prox&&(Fe=_i,Be=Ei,rt=Wi,wt=ii,St=si,mt=Hn,Ke=$i);else{let Gn=ht[We];Gn!=null&&(Ht[We]=_i,kn[We]=Ei,Dm(Gn,Wi,ii,si),Im(Gn,Hn,$i),ts(Gn,Si(_i),Si(Ei),z,Re))}}}}if(Ae){let We=ke.prox,$t=Zs==null?ls<=We:ls>We||Cs!=Zs;if(_e||$t){let Qt=ht[0];Qt!=null&&(Ht[0]=Fe,kn[0]=Be,Dm(Qt,rt,wt,St),Im(Qt,mt,Ke),ts(Qt,Si(Fe),Si(Be),z,Re))}}}if(Wt.show&&As)if(x!=null){let[ge,be]=cn.scales,[Ue,Fe]=cn.match,[Be,rt]=x.cursor.sync.scales,wt=x.cursor.drag;if(bn=wt._x,Sn=wt._y,bn||Sn){let{left:St,top:mt,width:Ke,height:We}=x.select,$t=x.scales[Be].ori,Qt=x.posToVal,wn,Ut,en,ni,Vn,gi=ge!=null&&Ue(ge,Be),wi=be!=null&&Fe(be,rt);gi&&bn?($t==0?(wn=St,Ut=Ke):(wn=mt,Ut=We),en=M[ge],ni=B(Qt(wn,Be),en,j,0),Vn=B(Qt(wn+Ut,Be),en,j,0),Io(Bi(ni,Vn),vn(Vn-ni))):Io(0,j),wi&&Sn?($t==1?(wn=St,Ut=Ke):(wn=mt,Ut=We),en=M[be],ni=D(Qt(wn,rt),en,ae,0),Vn=D(Qt(wn+Ut,rt),en,ae,0),Lo(Bi(ni,Vn),vn(Vn-ni))):Lo(0,ae)}else Ch()}else{let ge=vn(jd-Jd),be=vn(Qd-Kd);if(T.ori==1){let rt=ge;ge=be,be=rt}bn=Rn.x&&ge>=Rn.dist,Sn=Rn.y&&be>=Rn.dist;let Ue=Rn.uni;Ue!=null?bn&&Sn&&(bn=ge>=Ue,Sn=be>=Ue,!bn&&!Sn&&(be>ge?Sn=!0:bn=!0)):Rn.x&&Rn.y&&(bn||Sn)&&(bn=Sn=!0);let Fe,Be;bn&&(T.ori==0?(Fe=wr,Be=Gt):(Fe=Er,Be=Yt),Io(Bi(Fe,Be),vn(Be-Fe)),Sn||Lo(0,ae)),Sn&&(T.ori==1?(Fe=wr,Be=Gt):(Fe=Er,Be=Yt),Lo(Bi(Fe,Be),vn(Be-Fe)),bn||Io(0,j)),!bn&&!Sn&&(Io(0,0),Lo(0,0))}if(Rn._x=bn,Rn._y=Sn,x==null){if(N){if(ff!=null){let[ge,be]=cn.scales;cn.values[0]=ge!=null?Gi(T.ori==0?Gt:Yt,ge):null,cn.values[1]=be!=null?Gi(T.ori==1?Gt:Yt,be):null}No(hd,n,Gt,Yt,z,Re,U)}if(tt){let ge=N&&cn.setSeries,be=ke.prox;Zs==null?ls<=be&&Hi(Cs,Ar,!0,ge):ls>be?Hi(null,Ar,!0,ge):Cs!=Zs&&Hi(Cs,Ar,!0,ge)}}_e&&(ie.idx=U,Th()),w!==!1&&Mn("setCursor")}let Ps=null;Object.defineProperty(n,"rect",{get(){return Ps==null&&Do(!1),Ps}});function Do(x=!1){x?Ps=null:(Ps=g.getBoundingClientRect(),Mn("syncRect",Ps))}function nf(x,w,N,U,X,j,ae){he._lock||As&&x!=null&&x.movementX==0&&x.movementY==0||(Ah(x,w,N,U,X,j,ae,!1,x!=null),x!=null?Js(null,!0,!0):Js(w,!0,!1))}function Ah(x,w,N,U,X,j,ae,ge,be){if(Ps==null&&Do(!1),et(x),x!=null)N=x.clientX-Ps.left,U=x.clientY-Ps.top;else{if(N<0||U<0){Gt=-10,Yt=-10;return}let[Ue,Fe]=cn.scales,Be=w.cursor.sync,[rt,wt]=Be.values,[St,mt]=Be.scales,[Ke,We]=cn.match,$t=w.axes[0].side%2==1,Qt=T.ori==0?z:Re,wn=T.ori==1?z:Re,Ut=$t?j:X,en=$t?X:j,ni=$t?U:N,Vn=$t?N:U;if(St!=null?N=Ke(Ue,St)?a(rt,M[Ue],Qt,0):-10:N=Qt*(ni/Ut),mt!=null?U=We(Fe,mt)?a(wt,M[Fe],wn,0):-10:U=wn*(Vn/en),T.ori==1){let gi=N;N=U,U=gi}}be&&(w==null||w.cursor.event.type==hd)&&((N<=1||N>=z-1)&&(N=dr(N,z)),(U<=1||U>=Re-1)&&(U=dr(U,Re))),ge?(Jd=N,Kd=U,[wr,Er]=he.move(n,N,U)):(Gt=N,Yt=U)}let Rh={width:0,height:0,left:0,top:0};function Ch(){Wa(Rh,!1)}let sf,rf,of,af;function lf(x,w,N,U,X,j,ae){As=!0,bn=Sn=Rn._x=Rn._y=!1,Ah(x,w,N,U,X,j,ae,!0,!1),x!=null&&(yt(ud,gd,cf,!1),No(wm,n,wr,Er,z,Re,null));let{left:ge,top:be,width:Ue,height:Fe}=Wt;sf=ge,rf=be,of=Ue,af=Fe}function cf(x,w,N,U,X,j,ae){As=Rn._x=Rn._y=!1,Ah(x,w,N,U,X,j,ae,!1,!0);let{left:ge,top:be,width:Ue,height:Fe}=Wt,Be=Ue>0||Fe>0,rt=sf!=ge||rf!=be||of!=Ue||af!=Fe;if(Be&&rt&&Wa(Wt),Rn.setScale&&Be&&rt){let wt=ge,St=Ue,mt=be,Ke=Fe;if(T.ori==1&&(wt=be,St=Fe,mt=ge,Ke=Ue),bn&&Rs(b,Gi(wt,b),Gi(wt+St,b)),Sn)for(let We in M){let $t=M[We];We!=b&&$t.from==null&&$t.min!=zt&&Rs(We,Gi(mt+Ke,We),Gi(mt,We))}Ch()}else he.lock&&(he._lock=!he._lock,Js(w,!0,x!=null));x!=null&&(fn(ud,gd),No(ud,n,Gt,Yt,z,Re,null))}function P0(x,w,N,U,X,j,ae){if(he._lock)return;et(x);let ge=As;if(As){let be=!0,Ue=!0,Fe=10,Be,rt;T.ori==0?(Be=bn,rt=Sn):(Be=Sn,rt=bn),Be&&rt&&(be=Gt<=Fe||Gt>=z-Fe,Ue=Yt<=Fe||Yt>=Re-Fe),Be&&be&&(Gt=Gt<wr?0:z),rt&&Ue&&(Yt=Yt<Er?0:Re),Js(null,!0,!0),As=!1}Gt=-10,Yt=-10,q.fill(null),Js(null,!0,!0),ge&&(As=ge)}function hf(x,w,N,U,X,j,ae){he._lock||(et(x),Po(),Ch(),x!=null&&No(Am,n,Gt,Yt,z,Re,null))}function uf(){C.forEach(Fw),k(n.width,n.height,!0)}mr(rh,mo,uf);let Rr={};Rr.mousedown=lf,Rr.mousemove=nf,Rr.mouseup=cf,Rr.dblclick=hf,Rr.setSeries=(x,w,N,U)=>{let X=cn.match[2];N=X(n,w,N),N!=-1&&Hi(N,U,!0,!1)},fe&&(yt(wm,g,lf),yt(hd,g,nf),yt(Em,g,x=>{et(x),Do(!1)}),yt(Tm,g,P0),yt(Am,g,hf),wd.add(n),n.syncRect=Do);let $a=n.hooks=i.hooks||{};function Mn(x,w,N){zn?Dt.push([x,w,N]):x in $a&&$a[x].forEach(U=>{U.call(null,n,w,N)})}(i.plugins||[]).forEach(x=>{for(let w in x.hooks)$a[w]=($a[w]||[]).concat(x.hooks[w])});let df=(x,w,N)=>N,cn=un({key:null,setSeries:!1,filters:{pub:Bm,sub:Bm},scales:[b,y[1]?y[1].scale:null],match:[km,km,df],values:[null,null]},he.sync);cn.match.length==2&&cn.match.push(df),he.sync=cn;let ff=cn.key,Ph=Ug(ff);function No(x,w,N,U,X,j,ae){cn.filters.pub(x,w,N,U,X,j,ae)&&Ph.pub(x,w,N,U,X,j,ae)}Ph.sub(n);function I0(x,w,N,U,X,j,ae){cn.filters.sub(x,w,N,U,X,j,ae)&&Rr[x](null,w,N,U,X,j,ae)}n.pub=I0;function L0(){Ph.unsub(n),wd.delete(n),yn.clear(),vd(rh,mo,uf),l.remove(),me?.remove(),Mn("destroy")}n.destroy=L0;function Ih(){Mn("init",i,e),Co(e||i.data,!1),V[b]?Mh(b,V[b]):Po(),se=Wt.show&&(Wt.width>0||Wt.height>0),te=_e=!0,k(i.width,i.height)}return y.forEach(xr),C.forEach(ss),t?t instanceof HTMLElement?(t.appendChild(l),Ih()):t(n,Ih):Ih(),n}vt.assign=un;vt.fmtNum=Id;vt.rangeNum=oh;vt.rangeLog=ch;vt.rangeAsinh=Cd;vt.orient=_r;vt.pxRatio=Tt;vt.join=AM;vt.fmtDate=Dd,vt.tzDate=BM;vt.sync=Ug;{vt.addGap=yw,vt.clipGaps=dh;let i=vt.paths={points:Vg};i.linear=Gg,i.stepped=Mw,i.bars=ww,i.spline=Tw}var qg="#8b9bb0",gh="rgba(139,155,176,0.12)",Yg={raised:"#ef5350",changed:"#ffb020",cleared:"#38d39f"},Mo={left:"#4ea1ff",right:"#ffa94d",action:"#e05cff"},Vd={1:"#26c6da",2:"#c0ca33"},Ow="#90a4ae",wo=i=>i&&Vd[i.leg_id]||Ow,Zg="#ef5350",zd=14,Bw=2,kw=10,zw=new Set(["succeeded","sent"]),Vw=new Set(["held","canceled","replaced"]);function za(i){return zw.has(i)?"ok":Vw.has(i)?"warn":"danger"}function Jg(i){return i.outcome==="sent"||!i.end_known?"no end reported: drawn to its planned end":i.outcome==="held"?"held before its planned end":i.outcome==="replaced"?"the next leg was sent before its planned end":i.outcome||"ended"}var Hw={goal_sent:"goal sent",accepted:"goal accepted",rejected:"goal rejected",no_response:"no answer to the goal",failed:"goal failed",finished:"goal finished",cancel_requested:"cancel requested",monitor:"execution monitor",driver:"KUKA driver"},xh=i=>Hw[i]||i||"event";function Hd(i){return i.kind==="finished"?za(i.status||"finished"):i.kind==="rejected"||i.kind==="failed"||i.kind==="no_response"?"danger":i.kind==="driver"?i.status==="ready"?"ok":"warn":i.kind==="monitor"||i.kind==="cancel_requested"?"warn":"info"}function ns(i){return i==null?"–":`${i.toFixed(2)} s`}function mi(i){return String(i).replace(/[&<>"']/g,e=>({"&":"&amp;","<":"&lt;",">":"&gt;",'"':"&quot;","'":"&#39;"})[e])}var Gw=9,Ww="rgba(255,210,122,0.7)",_h=null;function $w(i){let e=vt.pxRatio;if(_h&&_h.px===e)return _h.pattern;let t=Math.max(4,Math.round(6*e)),n=document.createElement("canvas");n.width=t,n.height=t;let s=n.getContext("2d");s.fillStyle="rgba(255,210,122,0.12)",s.fillRect(0,0,t,t),s.strokeStyle="rgba(255,210,122,0.65)",s.lineWidth=1.2*e,s.beginPath();for(let o of[-t,0,t])s.moveTo(o,t),s.lineTo(o+t,0);s.stroke();let r=i.createPattern(n,"repeat");return _h={px:e,pattern:r},r}function Kg(i,e,{onSeek:t,cursorTime:n,height:s=190}){let r=e;if(!r.n)return i.innerHTML='<div class="empty">No frames were recorded, so there is no timeline.</div>',{redraw(){},destroy(){}};let o=Array.from(r.t),a=o[0],c=Math.max(o[o.length-1],a+.1),l=vt.paths.stepped({align:1}),d=[],u=r.robotLegs||[],h=r.robotHolds||[],m=(r.robotEvents||[]).filter(P=>P.kind!=="goal_sent"),g=r.partsTaken||[],v=u.length+h.length+m.length+g.length>0,p=Math.max(40,s-14-50),f=v?Math.max(7.6,7.2/(1-(zd+4)/p)):7.6,y={width:Math.max(200,i.clientWidth),height:s,padding:[14,12,0,0],scales:{x:{time:!1,range:[a,c]},y:{range:[0,f]}},axes:[{stroke:qg,grid:{stroke:gh,width:1},ticks:{stroke:gh,width:1},values:(P,I)=>I.map(q=>`${+q.toFixed(2)} s`),font:"11px system-ui, sans-serif"},{stroke:qg,grid:{stroke:gh,width:1},ticks:{stroke:gh,width:1},splits:()=>[0,1,2,3,4,5,6,7],values:(P,I)=>I.map(q=>q===0?"":String(q)),size:34,label:"score",labelSize:16,labelFont:"11px system-ui, sans-serif",font:"11px system-ui, sans-serif"}],series:[{label:"time",value:(P,I)=>ns(I)},{label:"grand score L",stroke:Mo.left,width:2,paths:l,points:{show:!1},value:(P,I)=>I??"–"},{label:"grand score R",stroke:Mo.right,width:2,paths:l,points:{show:!1},value:(P,I)=>I??"–"},{label:"action level",stroke:Mo.action,fill:"rgba(224,92,255,0.10)",width:1.5,dash:[5,4],paths:l,points:{show:!1},value:(P,I)=>I==null?"–":I===0?"not scored":I}],cursor:{drag:{x:!1,y:!1,setScale:!1},points:{show:!1},y:!1},legend:{show:!0,live:!0},hooks:{draw:[P=>{let I=P.ctx,{left:q,top:ie,width:he,height:Q}=P.bbox;I.save();for(let[le,me]of _){let pe=P.valToPos(le,"x",!0),De=P.valToPos(me,"x",!0);I.fillStyle="rgba(139,155,176,0.10)",I.fillRect(pe,ie,De-pe,Q),De-pe>60*vt.pxRatio&&(I.fillStyle="#8b9bb0",I.font=`${11*vt.pxRatio}px system-ui, sans-serif`,I.textAlign="center",I.fillText("no skeleton",(pe+De)/2,ie+14*vt.pxRatio))}if(F.length){let le=Gw*vt.pxRatio;I.fillStyle=$w(I),I.strokeStyle=Ww,I.lineWidth=1*vt.pxRatio;for(let[me,pe]of F){let De=Math.max(q,P.valToPos(me,"x",!0)),Ze=Math.min(q+he,P.valToPos(pe,"x",!0));if(Ze<=De)continue;let Ne=Math.max(1,Ze-De);I.fillRect(De,ie+Q-le,Ne,le),I.beginPath(),I.moveTo(De,ie+Q-le+.5),I.lineTo(De+Ne,ie+Q-le+.5),I.stroke()}}v&&M(P,I);for(let le of r.warnings){let me=Math.round(P.valToPos(le.t,"x",!0));me<q-1||me>q+he+1||(I.strokeStyle=Yg[le.kind]||"#ffb020",I.globalAlpha=.75,I.lineWidth=1.5*vt.pxRatio,I.setLineDash([3*vt.pxRatio,3*vt.pxRatio]),I.beginPath(),I.moveTo(me,ie),I.lineTo(me,ie+Q),I.stroke())}let fe=n();if(fe!=null){let le=Math.round(P.valToPos(fe,"x",!0));I.globalAlpha=1,I.setLineDash([]),I.strokeStyle="#f4f7fb",I.lineWidth=2*vt.pxRatio,I.beginPath(),I.moveTo(le,ie),I.lineTo(le,ie+Q),I.stroke()}I.restore()}],setSize:[P=>C(P)],ready:[P=>C(P)]}};function C(P){let I=P.over.clientWidth;for(let{el:q,t:ie,t1:he}of d){let Q=P.valToPos(ie,"x");if(he!=null){let fe=Math.max(0,Q),le=Math.min(I,P.valToPos(he,"x"));q.style.left=`${fe}px`,q.style.width=`${Math.max(0,le-fe)}px`,q.classList.toggle("tip-left",fe>I*.6),q.hidden=le-fe<1;continue}q.style.left=`${Q}px`,q.classList.toggle("tip-left",Q>I*.6),q.hidden=Q<-1||Q>I+1}}function M(P,I){let q=vt.pxRatio,{left:ie,top:he,width:Q}=P.bbox,fe=ie+Q;I.save(),I.globalAlpha=1,I.setLineDash([]),I.fillStyle="rgba(139,155,176,0.07)",I.fillRect(ie,he,Q,zd*q);let le=he+Bw*q,me=kw*q;I.font=`600 ${9.5*q}px system-ui, sans-serif`,I.textAlign="center",I.textBaseline="middle";for(let pe of u){let De=P.valToPos(pe.t_start,"x",!0),Ze=P.valToPos(pe.t_end,"x",!0),Ne=Math.max(ie,De),qe=Math.min(fe,Ze);if(qe-Ne<.5)continue;let ot=wo(pe);if(I.fillStyle=ot,pe.end_known)I.fillRect(Ne,le,qe-Ne,me),Ze<=fe&&(I.fillStyle=za(pe.outcome)==="danger"?Zg:"#0b1017",I.fillRect(qe-2*q,le,2*q,me));else{let bt=Ne+(qe-Ne)*.6;I.fillRect(Ne,le,bt-Ne,me);let At=I.createLinearGradient(bt,0,Math.max(bt+1,qe),0);At.addColorStop(0,ot),At.addColorStop(1,"rgba(0,0,0,0)"),I.fillStyle=At,I.fillRect(bt,le,qe-bt,me),I.strokeStyle=ot,I.lineWidth=1*q,I.setLineDash([3*q,2*q]),I.beginPath(),I.moveTo(bt,le+.5*q),I.lineTo(qe,le+.5*q),I.moveTo(bt,le+me-.5*q),I.lineTo(qe,le+me-.5*q),Ze<=fe&&(I.moveTo(qe-.5*q,le),I.lineTo(qe-.5*q,le+me)),I.stroke(),I.setLineDash([])}let Qe=pe.leg||"leg";I.measureText(Qe).width+10*q<qe-Ne&&(I.fillStyle="#0b1017",I.fillText(Qe,(Ne+qe)/2,le+me/2+.5*q))}I.fillStyle=Zg;for(let pe of h){let De=Math.round(P.valToPos(pe,"x",!0));De<ie-1||De>fe+1||I.fillRect(De-q,he,2*q,(zd+4)*q)}I.restore()}let R=[];for(let P=1;P<o.length;P++)R.push(o[P]-o[P-1]);R.sort((P,I)=>P-I);let b=R.length?R[R.length>>1]:0,_=[],A=Math.max(.5,3*b,e.overview?1.5*e.overview.bucketS:0);if(b>0)for(let P=1;P<o.length;P++)o[P]-o[P-1]>A&&_.push([o[P-1]+b,o[P]]);let H=[o,r.grandLeft,r.grandRight,r.actionLevel];if(_.length){let P=[[],[],[],[]],I=0;for(let q=0;q<o.length;q++){for(;I<_.length&&_[I][0]<o[q];){P[0].push(_[I][0]);for(let ie=1;ie<4;ie++)P[ie].push(null);I++}for(let ie=0;ie<4;ie++)P[ie].push(H[ie][q])}H.splice(0,4,...P)}let O=[],T=[];{let P=0;for(let I of H[0])P<o.length&&I===o[P]?(O.push(!!r.uncertainLeft[P]),T.push(!!r.uncertainRight[P]),P++):(O.push(!1),T.push(!1))}let F=[];for(let P=0;P<H[0].length;P++){if(!(O[P]||T[P]))continue;let I=H[0][P],q=P+1<H[0].length?H[0][P+1]:I+(b||.1),ie=F[F.length-1];ie&&Math.abs(ie[1]-I)<1e-9?ie[1]=q:F.push([I,q])}y.hooks.setLegend=[],r.hasUncertain&&y.hooks.setLegend.push(P=>{if(!B)return;let I=P.legend.idx,q=I==null?null:[O[I]&&"L",T[I]&&"R"].filter(Boolean);B.textContent=q==null?"–":q.length?q.join(" + "):"no"}),v&&y.hooks.setLegend.push(P=>{if(!D)return;let I=P.legend.idx,q=I==null?null:Xa(u,H[0][I]);D.textContent=I==null?"–":q?q.leg||"leg":"at rest"});let B=null,D=null,V=new vt(y,H,i);if(r.hasUncertain){let P=V.root.querySelector(".u-legend tbody");if(P){let I=document.createElement("tr");I.className="u-series u-unc",I.title="a side's score rests on low-confidence landmarks or held inputs",I.innerHTML='<th><div class="u-marker"></div><div class="u-label">uncertain (low-confidence landmarks)</div></th><td class="u-value">–</td>',P.appendChild(I),B=I.querySelector(".u-value")}}if(v){let P=V.root.querySelector(".u-legend tbody");if(P){let I=document.createElement("tr");I.className="u-series u-robot",I.title="the strip at the top: each robot leg (red ticks: holds; diamonds: controller events and parts taken)",I.innerHTML=`<th><div class="u-marker" style="background:linear-gradient(90deg, ${Vd[1]} 50%, ${Vd[2]} 50%)"></div><div class="u-label">robot leg</div></th><td class="u-value">–</td>`,P.appendChild(I),D=I.querySelector(".u-value")}}for(let P of r.warnings){let I=document.createElement("div");I.className=`wmark ${Yg[P.kind]?P.kind:"changed"}`;let q=P.side?`${P.side} `:"";I.innerHTML=`<div class="flag"></div><div class="tip"><b>${ns(P.t)} · ${mi(P.kind||"")}</b> ${mi(q+(P.region||""))}${P.score!=null?` · score ${mi(P.score)}`:""}${P.action_level!=null?` · action level ${mi(P.action_level)}`:""}<br>${mi(P.message||"")}</div>`,I.setAttribute("aria-label",`${P.kind} warning at ${ns(P.t)}: ${P.message||""}`),V.over.appendChild(I),d.push({el:I,t:P.t})}for(let P of u){let I=document.createElement("div");I.className=`rmark leg ${za(P.outcome)}`,I.dataset.color=wo(P),I.dataset.leg=P.leg,I.dataset.t=String(P.t_start),I.dataset.tEnd=String(P.t_end);let q=P.t_end-P.t_start,ie=P.planned_s!=null?` · planned ${P.planned_s.toFixed(2)} s`:"",he=P.feedback_count!=null?`<br>${P.feedback_count} feedback message${P.feedback_count===1?"":"s"}${P.max_error!=null?` · largest joint error ${P.max_error.toFixed(4)} rad`:""}`:"";I.innerHTML=`<div class="tip"><b>${mi(P.leg||"robot leg")}</b> ${ns(P.t_start)} – ${ns(P.t_end)} (${q.toFixed(2)} s${ie})<br>${mi(Jg(P))}${he}${P.text?`<br>${mi(P.text)}`:""}</div>`,I.setAttribute("aria-label",`robot leg ${P.leg} at ${ns(P.t_start)}: ${Jg(P)}`),V.over.appendChild(I),d.push({el:I,t:P.t_start,t1:P.t_end})}for(let P of m){let I=document.createElement("div");I.className=`rmark ev ${Hd(P)}`;let q=[P.leg,P.status,P.kind==="finished"&&P.error_code?`error code ${P.error_code}`:"",P.kind==="monitor"&&P.max_error!=null?`worst ${(P.max_error*100).toFixed(0)} % of the tolerance`:""].filter(Boolean).join(" · ");I.innerHTML=`<div class="flag"></div><div class="tip"><b>${ns(P.t)} · ${mi(xh(P.kind))}</b>${q?` ${mi(q)}`:""}${P.text?`<br>${mi(P.text)}`:""}</div>`,I.setAttribute("aria-label",`${xh(P.kind)} at ${ns(P.t)}`),V.over.appendChild(I),d.push({el:I,t:P.t})}for(let P of g){let I=document.createElement("div");I.className="rmark ev part";let q=[P.hand?`${P.hand} hand`:"",P.distance_m!=null?`came to ${P.distance_m.toFixed(3)} m of the handover point`:""].filter(Boolean).join(", ");I.innerHTML=`<div class="flag"></div><div class="tip"><b>${ns(P.t)} · part ${P.part??""} taken</b>${q?` ${mi(q)}`:""}<br>${mi(P.reason)}</div>`,I.setAttribute("aria-label",`part ${P.part??""} taken at ${ns(P.t)}`),V.over.appendChild(I),d.push({el:I,t:P.t})}C(V),V.over.addEventListener("click",P=>{let I=V.over.getBoundingClientRect(),q=Math.min(Math.max(0,P.clientX-I.left),I.width);t(V.posToVal(q,"x"))}),V.over.style.cursor="pointer",V.over.title="";let Y=new ResizeObserver(()=>{let P=Math.max(200,i.clientWidth);Math.abs(P-V.width)>1&&V.setSize({width:P,height:s})});Y.observe(i);let $=!1;V.over.addEventListener("mouseenter",()=>$=!0),V.over.addEventListener("mouseleave",()=>{$=!1,ce()});function ce(){let P=n();$||(P==null?V.setLegend({idx:null}):V.setLegend({idx:Cr(H[0],P)}))}return{redraw(){V.redraw(!1,!1),ce()},destroy(){Y.disconnect(),V.destroy()}}}var is=["#4ea1ff","#ffa94d"],jg="#8b9bb0",Gd="rgba(139,155,176,0.12)";function Le(i){return String(i??"").replace(/[&<>"']/g,e=>({"&":"&amp;","<":"&lt;",">":"&gt;",'"':"&quot;","'":"&#39;"})[e])}var Qg=i=>String(+(+i).toFixed(1)),dn=(i,e=1)=>i==null||!Number.isFinite(+i)?"–":(+i).toFixed(e),Eo=i=>String(i||"").replace(/^./,e=>e.toUpperCase());function Xw(i){return i==null?"–":i<1024?`${i} B`:i<1024*1024?`${(i/1024).toFixed(1)} KiB`:`${(i/1024/1024).toFixed(1)} MiB`}function qw(i){if(i.height_m==null)return'<span class="muted">not measured</span>';let e=i.height_uncertainty_m!=null?` ± ${(i.height_uncertainty_m*100).toFixed(1)} cm`:"";return`${i.height_m.toFixed(3)} m${e}`}var Yw={interval:"its stature interval lies inside the class",expected_rula:"across a boundary: the lowest expected RULA",most_probable:"across a boundary: the most probable class"};function Zw(i){if(!i.height_class)return'<span class="muted">undecided</span>';let e=`<span class="badge">${Le(i.height_class)}</span>`;if(i.class_probability==null)return e;let t=Yw[i.decision_basis]??i.decision_basis??"",n=i.expected_rula_cost!=null?`, expected RULA cost ${i.expected_rula_cost>=0?"+":""}${i.expected_rula_cost.toFixed(2)}`:"",s=i.expected_rula_cost,r=`<br><span class="muted small cost-note">Probability: the chance that the operator's stature lies in this class (measured height and its uncertainty).${s==null?"":` Expected RULA cost: the handover's expected RULA grand score (points, 1–7) with this class's trajectory minus with the operator's own class's, over the stature's uncertainty (the twin's curves). ${Math.abs(s)<.05?"Near 0: no difference in practice.":s<0?"Negative: this class is expected to suit the operator better.":"Positive: expected that much worse, the price of an uncertain class."}`}</span>`;return`${e} <span class="small">probability ${i.class_probability.toFixed(2)}${n}</span><br><span class="muted small">${Le(t)}</span>${r}`}function Jw(i){return i?`<code title="${Le(i)}">${Le(String(i).slice(0,12))}…</code>`:'<span class="muted">none locked</span>'}function Kw(i){return i.approved_by.length?i.approved_by.map(e=>`<span class="badge ok">${Le(e)}</span>`).join(" "):'<span class="badge warn">not approved</span>'}function jw(i){let e=i.source,t=[Xw(e.bytes),e.messages!=null?`${e.messages} messages`:null,i.overview?`${i.overview.recorded} frames (${i.n} on this page)`:`${i.n} frames`],n=i.n>1?` · ${(i.t[i.n-1]-i.t[0]).toFixed(1)} s`:"",s=e.complete?'<span class="badge ok">complete</span>':'<span class="badge danger">incomplete</span>';return`${t.filter(Boolean).join(" · ")}${n} ${s}`}function r0(i,e){let t=[["Recording",n=>`<span class="file" title="${Le(n.source.file??n.label)}">${Le(n.source.file??n.label)}</span><br><span class="muted small">${jw(n)}</span>`],["Operator height",n=>qw(n.facts)],["Height class",n=>Zw(n.facts)],["Locked trajectory",n=>Jw(n.facts.trajectory_sha256)],["Approved by",n=>Kw(n.facts)],["Parts taken",n=>n.hasPartsTaken?String(n.partsTaken.length):'<span class="muted">not recorded</span>']];if(e.length===1){let n=e[0];i.innerHTML=`<h2>Session facts</h2><dl class="facts">${t.map(([s,r])=>`<dt>${s}</dt><dd>${r(n)}</dd>`).join("")}</dl>`}else i.innerHTML=`<h2>Session facts</h2><table class="facts-table"><thead><tr><th></th>${e.map((n,s)=>`<th><span class="sess-dot" style="background:${is[s]}"></span>${"AB"[s]}</th>`).join("")}</tr></thead><tbody>${t.map(([n,s])=>`<tr><th>${n}</th>${e.map(r=>`<td>${s(r)}</td>`).join("")}</tr>`).join("")}</tbody></table>`}function o0(i,e,t){let n=e.map((s,r)=>{let o=s.facts.states.map(c=>{let l=Number(c.t);return`<li><button class="linkish" data-s="${r}" data-t="${Number.isFinite(l)?l:""}"><span class="t">${dn(l,2)} s</span><span class="state state-${Le(c.state)}">${Le(String(c.state??"").replace(/_/g," "))}</span></button>${c.reason?`<span class="reason">${Le(c.reason)}</span>`:""}</li>`}).join("");return`${e.length>1?`<h3><span class="sess-dot" style="background:${is[r]}"></span>${"AB"[r]} · ${Le(s.label)}</h3>`:""}<ol class="events">${o||'<li class="muted">no state changes recorded</li>'}</ol>`});i.innerHTML=`<h2>State changes</h2><div class="scroll">${n.join("")}</div>`,Xd(i,t)}var Qw=new Set(["rejected","failed","no_response","cancel_requested","monitor","driver"]);function e1(i){return!i.end_known||i.outcome==="sent"?'<span class="badge" title="nothing reported its end: drawn to its planned end">sent · end planned</span>':`<span class="badge ${za(i.outcome)}">${Le(String(i.outcome||"ended").replace(/_/g," "))}</span>`}function a0(i,e,t){let n=e.map((r,o)=>{let c=[...r.robotLegs.map(h=>({t:h.t_start,html:`<span class="leg-name"><i class="leg-chip" style="background:${wo(h)}"></i>${Le(h.leg||"leg")}</span></button><span class="dur" title="${h.planned_s!=null?`planned ${h.planned_s.toFixed(2)} s`:""}">${(h.t_end-h.t_start).toFixed(2)} s</span>${e1(h)}${h.feedback_count!=null?`<span class="reason">${h.feedback_count} feedback message${h.feedback_count===1?"":"s"}${h.max_error!=null?` · largest joint error ${h.max_error.toFixed(4)} rad`:""}</span>`:""}${h.text?`<span class="reason">${Le(h.text)}</span>`:""}`})),...r.robotHolds.map(h=>({t:h,html:'<span class="kind kind-raised">hold</span></button>'})),...r.partsTaken.map(h=>({t:h.t,html:`<span class="kind kind-cleared">part ${Le(h.part??"")} taken</span></button>${h.hand?`<span class="muted small">${Le(h.hand)} hand</span>`:""}`})),...r.robotEvents.filter(h=>Qw.has(h.kind)).map(h=>{let m=Hd(h),g=m==="danger"?"raised":m==="ok"?"cleared":"changed";return{t:h.t,html:`<span class="kind kind-${g}">${Le(xh(h.kind))}${h.status?` · ${Le(h.status.replace(/_/g," "))}`:""}</span></button>${h.text?`<span class="reason">${Le(h.text)}</span>`:""}`}})].sort((h,m)=>h.t-m.t).map(h=>`<li><button class="linkish" data-s="${o}" data-t="${h.t}"><span class="t">${dn(h.t,2)} s</span>${h.html}</li>`).join(""),l=(h,m,g)=>`${h} ${h===1?m:g}`,d=r.robotLegs.length||r.robotHolds.length||r.robotEvents.length?`<div class="robot-sum">${[l(r.robotLegs.length,"leg","legs"),r.hasPartsTaken?l(r.partsTaken.length,"part taken","parts taken"):null,l(r.robotHolds.length,"hold","holds"),r.robotEvents.length?l(r.robotEvents.length,"controller event","controller events"):null].filter(Boolean).join(" · ")}</div>`:"";return`${e.length>1?`<h3><span class="sess-dot" style="background:${is[o]}"></span>${"AB"[o]} · ${Le(r.label)}</h3>`:""}${d}<ol class="events">${c||'<li class="muted">no robot commands recorded</li>'}</ol>`}),s=e.reduce((r,o)=>r+o.robotLegs.length,0);i.innerHTML=`<h2>Robot <span class="count" title="legs">${s}</span><span class="hint">legs sent, holds, parts taken; click to jump</span></h2><div class="scroll">${n.join("")}</div>`,Xd(i,t)}function t1(i){let e=typeof i.band_probability=="number"&&Number.isFinite(i.band_probability)?i.band_probability:null;return e===null?' <span class="sure muted">· how sure: not known</span>':` <span class="sure${i.near_limit?" near":""}">· ${Math.round(e*100)} % sure${i.near_limit?", near the limit":""}</span>`}function l0(i,e,t){let n=e.map((r,o)=>{let a=r.warnings.map(l=>`<li><button class="linkish" data-s="${o}" data-t="${l.t}"><span class="t">${dn(l.t,2)} s</span><span class="kind kind-${Le(l.kind)}">${Le(l.kind)}</span></button><span class="reason">${Le(l.message||`${l.side} ${l.region}`)}${t1(l)}</span></li>`).join("");return`${e.length>1?`<h3><span class="sess-dot" style="background:${is[o]}"></span>${"AB"[o]} · ${Le(r.label)}</h3>`:""}<ol class="events">${a||'<li class="muted">no posture warnings</li>'}</ol>`}),s=e.reduce((r,o)=>r+o.warnings.length,0);i.innerHTML=`<h2>Posture warnings <span class="count">${s}</span></h2><div class="scroll">${n.join("")}</div>`,Xd(i,t)}function Xd(i,e){i.querySelectorAll("button[data-t]").forEach(t=>{t.addEventListener("click",()=>{let n=parseFloat(t.dataset.t);Number.isFinite(n)&&e(Number(t.dataset.s),n)})})}function c0(i){return`${i.name}|${i.side||""}`}function h0(i,e){return(i.scale??(i.name==="action level"?"action_level":i.name==="REBA score"||e>uo?"reba":"rula"))==="rula"?n=>Qc(n):n=>ld(n,e)}function Wd(i,e){if(!i)return'<div class="sharebar empty-bar"><span class="muted small">not scored</span></div>';let t=Math.max(1,Number(i.max_score)||(i.time_share||[]).length||1),n=h0(i,t),s=Array.isArray(i.time_share)?i.time_share:[];if(!s.some(o=>Number(o)>0))return`<div class="sharebar">${e?`<span class="tag">${e}</span>`:""}<div class="bar"></div><span class="muted small">no scored frames</span></div>`;let r=s.map((o,a)=>{let c=Math.max(0,Number(o)||0)*100;if(c<=0)return"";let l=c>=7?`${a+1}`:"";return`<span class="seg" style="width:${c.toFixed(2)}%;background:${n(a+1)}" title="score ${a+1}: ${c.toFixed(1)} % of scored time">${l}</span>`}).join("");return`<div class="sharebar">${e?`<span class="tag">${e}</span>`:""}<div class="bar">${r}</div></div>`}function $d(i){if(!i||i.mean==null)return'<span class="muted">–</span>';let e=Math.max(1,Number(i.max_score)||1);return`<span class="chip" style="background:${h0(i,e)(Math.min(e,Math.max(1,i.mean)))}"></span>${dn(i.mean,2)}`}function n1(i){let e=(i&&Array.isArray(i.exposure)?i.exposure:[]).filter(t=>t.episodes>0);return e.length?e.map(t=>`<span class="expo" title="score ≥ ${t.at_least}: ${t.episodes} episode(s), longest ${dn(t.longest_secs,1)} s, ${dn(t.total_secs,1)} s in all">≥${t.at_least} ${t.episodes}× ${dn(t.longest_secs,1)} s</span>`).join(" · "):'<span class="muted">–</span>'}function u0(i,e){let t=[],n=e.map(l=>{let d=new Map;for(let u of l.regions){let h=c0(u);t.includes(h)||t.push(h),d.set(h,u)}return d});if(!t.length){i.innerHTML='<h2>Body regions</h2><div class="empty">No RULA scores in this recording.</div>';return}let s=e.length>1,r=l=>{let d=l&&l.time_share||[];for(let u=d.length-1;u>=0;u--)if(Number(d[u])>0)return u+1;return"–"},o="the highest score reached / the top of the row's scale",a=s?`<tr><th>Region</th><th class="num">mean A</th><th class="num">mean B</th><th class="num">Δ B−A</th><th class="num" title="${o}">highest A, B / top</th><th>Share of scored time per score (A above B)</th></tr>`:`<tr><th>Region</th><th class="num">mean</th><th class="num" title="${o}">highest / top</th><th>Share of scored time per score</th><th title="per score level reached: separate stretches at or above it × the longest stretch">Exposure: episodes × longest</th></tr>`,c=t.map(l=>{let d=n.map(f=>f.get(l)),u=d.find(Boolean),h=`${u.side?`${Eo(u.side)} `:""}${u.name}`,m=u.max_score??"–";if(!s)return`<tr><th>${Le(Eo(h))}</th><td class="num">${$d(d[0])}</td><td class="num">${Le(r(d[0]))} / ${Le(m)}</td><td>${Wd(d[0])}</td><td class="small">${n1(d[0])}</td></tr>`;let[g,v]=d,p='<span class="muted">–</span>';if(g&&v&&g.mean!=null&&v.mean!=null){let f=v.mean-g.mean;p=`<span class="${f<-.05?"better":f>.05?"worse":"muted"}">${f>0?"+":""}${f.toFixed(2)}</span>`}return`<tr><th>${Le(Eo(h))}</th><td class="num">${$d(g)}</td><td class="num">${$d(v)}</td><td class="num">${p}</td><td class="num">${Le(r(g))}, ${Le(r(v))} / ${Le(m)}</td><td>${Wd(g,"A")}${Wd(v,"B")}</td></tr>`}).join("");i.innerHTML=`<h2>Body regions <span class="hint">RULA score per region, grand score per side and the worse side's action level; REBA score per side below when recorded; bar segments coloured by score, as in the 3D view: 1 deep blue … 7 deep red, the same colour for the same score in every row; "top" is the highest score the row's scale has</span></h2><table class="regions"><thead>${a}</thead><tbody>${c}</tbody></table>`}function e0(i,e,t){let n=Array.isArray(i)?i.map(r=>Math.max(0,Number(r)||0)):[];return n.some(r=>r>0)?`<div class="sharebar"><div class="bar">${n.map((r,o)=>{let a=r*100;if(a<=0)return"";let c=o+e;return`<span class="seg" style="width:${a.toFixed(2)}%;background:${ld(o+1,n.length)}" title="${t} ${c}: ${a.toFixed(1)} %">${a>=9?c:""}</span>`}).join("")}</div></div>`:'<span class="muted small">–</span>'}function i1(i){return i.not_acceptable_secs>4||i.limit_secs==null?`${dn(i.duration_secs,1)} s, ${dn(i.not_acceptable_secs,1)} s of it in a zone not acceptable at any duration (up to ${dn(i.peak_deg,0)}°)`:`${dn(i.duration_secs,1)} s, longer than the ${dn(i.limit_secs,0)} s allowed at its largest angle (up to ${dn(i.peak_deg,0)}°)`}var t0="the worse side's RULA grand score plus how far its angles lie into their bands, time-weighted over the frames whose angles were all observed";function n0(i){return i&&i.secs>0?dn(i.point_secs/i.secs,3):"–"}function d0(i,e){let t=e[0],n=t.summary||{},s=Array.isArray(n.phases)?n.phases:[],r=Array.isArray(n.static_postures)?n.static_postures:[],o=Array.isArray(n.reba_score)&&n.reba_score.length>0,c=`<h2>Task segments${e.length>1?` <span class="hint">session A (${Le(t.label)})</span>`:""} <span class="hint">from the skeleton (walking, floor pick) and the robot (handover: a part on its way or waiting); action level of the worse side per segment</span></h2>`;if(!s.length)c+='<div class="empty">No task segments: the recording has no skeletons with hips.</div>';else{let l=s.map(d=>{let u=(d.action_level_exposure||[]).find(m=>m.at_least===3),h=u&&u.episodes>0?`${u.episodes}× · longest ${dn(u.longest_secs,1)} s`:'<span class="muted">–</span>';return`<tr data-phase="${Le(d.phase)}"><th>${Le(Eo(d.phase))}</th><td class="num">${dn(d.duration_secs,1)} s</td><td class="num">${dn(d.time_share*100,1)} %</td><td class="num">${Le(d.episodes)}</td><td>${e0(d.action_level_share,1,"action level")}</td><td class="small">${h}</td>${o?`<td>${e0(d.reba_action_level_share,0,"REBA action level")}</td>`:""}<td class="num">${d.peak_grand_score??"–"}</td><td class="num posture-cost">${n0(d.posture_cost)}</td></tr>`}).join("");c+=`<table class="regions segments"><thead><tr><th>Segment</th><th class="num">time</th><th class="num">share</th><th class="num">episodes</th><th>RULA action level 1–4</th><th>at level ≥ 3</th>${o?"<th>REBA action level 0–4</th>":""}<th class="num">peak grand</th><th class="num" title="${t0}">posture cost</th></tr></thead><tbody>${l}</tbody></table>`,c+=`<div class="hint session-cost">Posture cost over the session: <span class="num">${n0(n.posture_cost)}</span> (${t0})</div>`}if(c+=`<h2 class="sub">Static postures <span class="hint">ISO 11226: held &gt; 4 s outside the acceptable zone · trunk 20°–60° for at most 4 min at 20° down to 1 min at 60°; beyond 60° or extended, and the neck outside 0°–25°, not acceptable · upper arm (from vertical) beyond 60° not acceptable; its 20°–60° holding-time curve has no readable source, so those holds are counted for you to judge · ergocell's: extension counts beyond 5°, a return to the zone shorter than 1 s does not end a hold</span></h2>`,!r.length)c+='<div class="empty">No trunk or neck angles in this recording.</div>';else{let l=r.map(d=>{let u=(d.holds||[]).filter(v=>v.exceeded).sort((v,p)=>p.duration_secs-v.duration_secs)[0],h=u?i1(u):'<span class="muted">–</span>',m=d.exceeded>0?`<span class="badge danger">${Le(d.exceeded)}</span>`:'<span class="badge ok">0</span>',g=d.limit_unknown>0?`<span class="badge warn" title="held 20°–60°: ISO 11226 limits this by a holding time no readable source gives — judge them">${Le(d.limit_unknown)}</span>`:'<span class="muted">0</span>';return`<tr data-part="${Le(d.part)}"><th>${Le(Eo(String(d.part).replace(/_/g," ")))}</th><td class="num">${Le(d.static_holds)}</td><td class="num">${m}</td><td class="num">${g}</td><td class="num">${dn(d.longest_secs,1)} s</td><td class="small">${h}</td></tr>`}).join("");c+=`<table class="regions statics"><thead><tr><th>Body part</th><th class="num">static holds</th><th class="num">not acceptable</th><th class="num">no known limit</th><th class="num">longest</th><th>worst not acceptable</th></tr></thead><tbody>${l}</tbody></table>`}i.innerHTML=c}function s1(i,e){return i.length===e.length&&i.every((t,n)=>Math.abs(t-e[n])<1e-9)}function vh(i){let e=i[1]-i[0];return e>0&&i.every((t,n)=>n===0||Math.abs(t-i[n-1]-e)<1e-6*e)?e:null}function r1(i,e){let t=i.bin_edges.map(Number),n=e.bin_edges.map(Number);if(s1(t,n))return{edges:t,counts:[i.counts,e.counts]};let s=vh(t);if(s===null||vh(n)===null||Math.abs(vh(n)-s)>1e-6*s)return null;let r=(n[0]-t[0])/s;if(Math.abs(r-Math.round(r))>1e-6)return null;let o=Math.min(t[0],n[0]),a=Math.round((Math.max(t[t.length-1],n[n.length-1])-o)/s),c=Array.from({length:a+1},(d,u)=>o+u*s),l=(d,u)=>{let h=new Array(a).fill(0),m=Math.round((d[0]-o)/s);return u.forEach((g,v)=>h[m+v]=Number(g)||0),h};return{edges:c,counts:[l(t,i.counts),l(n,e.counts)]}}var i0="rgba(255,128,80,0.85)",s0=30;function o1(i,e){let t=i[0],n=i[i.length-1],s=e.filter(o=>o>=t-s0&&o<=n+s0),r=5;for(let o of s)o-r<t&&(t=o-r),o+r>n&&(n=o+r);return[t,n]}function a1(i,e,t,n=[]){let[s,r]=o1(e,n),o=0,a=vh(e);if(a!==null&&(s<e[0]||r>e[e.length-1])){o=Math.ceil((e[0]-s)/a-1e-9);let v=Math.ceil((r-e[e.length-1])/a-1e-9),p=e[0]-o*a;e=Array.from({length:e.length+o+v},(f,y)=>p+y*a),[s,r]=[e[0],e[e.length-1]]}let c=e.slice(0,-1).map((v,p)=>(v+e[p+1])/2),l=[{label:"angle",value:(v,p)=>p==null?"–":`${p.toFixed(0)}°`}],d=[c],u=t.length>1,h=n.filter(v=>v>=s&&v<=r);h.length&&(i.title=`RULA score changes at ${h.map(v=>`${Qg(v)}°`).join(", ")} (dotted lines)`),t.forEach((v,p)=>{let f=v.counts.reduce((y,C)=>y+(Number(C)||0),0)||1;d.push(c.map((y,C)=>C<o||C-o>=v.counts.length?null:(Number(v.counts[C-o])||0)/f*100)),l.push({label:u?"AB"[p]:"% of samples",stroke:v.color,fill:`${v.color}${u?"bb":"99"}`,width:1,paths:vt.paths.bars({size:[u?.45:.86,1/0],align:u?p===0?-1:1:0}),points:{show:!1},value:(y,C)=>C==null?"–":`${C.toFixed(1)} %`})});let m=Math.max(180,i.clientWidth),g=new vt({width:m,height:150,padding:[h.length?14:8,16,0,0],legend:{show:!1},cursor:{drag:{x:!1,y:!1,setScale:!1},points:{show:!1},y:!1},scales:{x:{time:!1,range:[s,r]},y:{range:(v,p,f)=>[0,Math.max(5,Math.ceil(f/5)*5)]}},axes:[{stroke:jg,grid:{show:!1},ticks:{stroke:Gd},values:(v,p)=>p.map(f=>`${f}°`),font:"10px system-ui, sans-serif",size:28},{stroke:jg,grid:{stroke:Gd},ticks:{stroke:Gd},values:(v,p)=>p.map(f=>`${f}%`),font:"10px system-ui, sans-serif",size:40}],series:l,hooks:{draw:[v=>{let p=v.ctx,{top:f,height:y}=v.bbox,C=vt.pxRatio;p.save(),p.strokeStyle=i0,p.fillStyle=i0,p.lineWidth=1.2*C,p.setLineDash([1.5*C,2.5*C]),p.font=`${9*C}px system-ui, sans-serif`,p.textAlign="center",p.textBaseline="bottom";let M=-1/0;for(let R of h){let b=Math.round(v.valToPos(R,"x",!0))+.5;p.beginPath(),p.moveTo(b,f),p.lineTo(b,f+y),p.stroke();let _=`${Qg(R)}°`,A=p.measureText(_).width;b-A/2<M+3*C||(p.fillText(_,b,f-1*C),M=b+A/2)}for(let R of t)for(let[b,_]of[[R.mean,[]],[R.p95,[4,3]]]){if(b==null||!Number.isFinite(b))continue;let A=Math.round(v.valToPos(b,"x",!0));p.strokeStyle=u?R.color:"#f4f7fb",p.lineWidth=1.5*vt.pxRatio,p.setLineDash(_.map(H=>H*vt.pxRatio)),p.beginPath(),p.moveTo(A,f),p.lineTo(A,f+y),p.stroke()}p.restore()}]}},d,i);new ResizeObserver(()=>{let v=Math.max(180,i.clientWidth);Math.abs(v-g.width)>1&&g.setSize({width:v,height:150})}).observe(i)}var l1={"trunk flexion":"forward +, extension −","trunk side bend":"towards the right +, left −","neck flexion":"forward +, extension −","neck side bend":"unsigned: either side is +","upper arm flexion":"flexion +, extension −","upper arm abduction":"outwards +, across the chest −","elbow flexion":"0° = straight arm","wrist flexion":"towards the palm +, extension −"};function f0(i,e){let t=[],n=e.map(a=>{let c=new Map;for(let l of a.angles){let d=c0(l);t.includes(d)||t.push(d),c.set(d,l)}return c}),r=e.some(a=>a.angles.some(c=>c.score_edges_deg.length))?'<div class="angle-legend"><i class="edge-swatch"></i>dotted: where the RULA score changes</div>':"";i.innerHTML=`<h2>Joint angles <span class="hint">distribution over the scored frames · solid line mean, dashed line 95th percentile</span></h2>${r}<div class="angle-grid"></div>`;let o=i.querySelector(".angle-grid");if(!t.length){o.outerHTML='<div class="empty">No joint angles in this recording.</div>';return}for(let a of t){let c=n.map(R=>R.get(a)),l=c.find(Boolean),d=l.unit==="deg"||!l.unit?"°":` ${Le(l.unit)}`,u=document.createElement("div");u.className="angle";let h=c.map((R,b)=>{let _=e.length>1?`<span class="sess-dot" style="background:${is[b]}"></span>${"AB"[b]} `:"";return R?`<div class="stats">${_}mean <b>${dn(R.mean)}${d}</b> · p95 <b>${dn(R.p95)}${d}</b> · n ${Le(R.samples??"–")}</div>`:`<div class="stats">${_}<span class="muted">not recorded</span></div>`}).join(""),m=[...new Set(c.flatMap(R=>R?R.score_edges_deg:[]))].sort((R,b)=>R-b),g=l1[String(l.name)],v=`<div class="sign"${g?' title="sign convention (ergonomics/src/angles.rs)"':""}>${g?Le(g):"&nbsp;"}</div>`;u.innerHTML=`<div class="angle-head"><span class="name">${Le(Eo(`${l.side?`${l.side} `:""}${l.name}`))}</span></div>${v}${h}<div class="plots"></div>`,o.appendChild(u);let p=u.querySelector(".plots"),f=c.map((R,b)=>({a:R,i:b})).filter(({a:R})=>R&&Array.isArray(R.bin_edges)&&R.bin_edges.length>=2&&Array.isArray(R.counts)&&R.counts.some(b=>Number(b)>0));if(!f.length){p.innerHTML='<div class="empty small">no samples</div>';continue}let y=R=>e.length>1?is[R]:"#5b8def",C=(R,b)=>{let _=document.createElement("div");_.className="hist",p.appendChild(_),a1(_,R,b,m)},M=f.length===2?r1(f[0].a,f[1].a):null;if(M)C(M.edges,f.map(({a:R,i:b},_)=>({counts:M.counts[_],mean:R.mean,p95:R.p95,color:y(b)})));else for(let{a:R,i:b}of f)C(R.bin_edges.map(Number),[{counts:R.counts,mean:R.mean,p95:R.p95,color:y(b)}])}}var c1=["","acceptable","investigate; change may be needed","investigate and change soon","investigate and change now"];function h1(i,e){let t=`${To(e,0)} s`,n={change:["Change","danger",`held at or past its warning score for ${t} or more, or the operator was warned`],brief:["Brief","warn",`reached its warning score only for moments under ${t}`],acceptable:["Acceptable","ok","never at its warning score"],not_scored:["Not scored","","never seen well enough to score"]};return Object.hasOwn(n,i)?n[i]:[String(i),"",""]}var To=(i,e=1)=>i==null||!Number.isFinite(+i)?"–":(+i).toFixed(e),Yd=i=>String(i||"").replace(/^./,e=>e.toUpperCase());function Va(i){if(!Number.isFinite(i))return"–";if(i<9.95)return`${i.toFixed(1)} s`;let e=Math.round(i);if(e<60)return`${e} s`;if(e<3600)return`${Math.floor(e/60)} min ${String(e%60).padStart(2,"0")} s`;let t=Math.round(i/60);return`${Math.floor(t/60)} h ${String(t%60).padStart(2,"0")} min`}var p0=11,m0=12,g0=23,_0=24,qd=(i,e)=>[i[0]-e[0],i[1]-e[1],i[2]-e[2]],yh=(i,e)=>i[0]*e[0]+i[1]*e[1]+i[2]*e[2],u1=(i,e)=>[i[1]*e[2]-i[2]*e[1],i[2]*e[0]-i[0]*e[2],i[0]*e[1]-i[1]*e[0]],d1=i=>{let e=Math.hypot(...i);return e>1e-9?i.map(t=>t/e):null};function f1(i,e){let t=o=>[i[3*o],i[3*o+1],i[3*o+2]],n=o=>Number.isFinite(i[3*o]),s=null;if(n(p0)&&n(m0)?s=qd(t(m0),t(p0)):n(g0)&&n(_0)&&(s=qd(t(_0),t(g0))),!s)return null;let r=d1(qd(s,e.map(o=>o*yh(s,e))));return r?{up:e,across:r,forward:u1(e,r)}:null}function p1(i,e){let t=i.positions[e],n=i.strain[e],s=t&&f1(t,i.up);if(!s)return'<div class="still-missing muted small">no skeleton at this moment</div>';let r=[];for(let b=0;b<i.nl;b++){if(!Number.isFinite(t[3*b])){r.push(null);continue}let _=[t[3*b],t[3*b+1],t[3*b+2]];r.push({front:-yh(_,s.across),side:yh(_,s.forward),h:yh(_,s.up)})}let o=r.filter(Boolean),a=o.map(b=>b.h),c=o.map(b=>b.front),l=o.map(b=>b.side),d=b=>[Math.min(...b),Math.max(...b)],[u,h]=d(a),[m,g]=d(c),[v,p]=d(l),f=118,y=7,C=(f-2*y)/Math.max(.5,h-u),M=(b,_)=>Math.max(60,(_-b)*C+2*y),R=(b,_,A,H)=>{let O=M(_,A),T=(_+A)/2,F=Y=>(O/2+(Y[b]-T)*C).toFixed(1),B=Y=>(y+(h-Y.h)*C).toFixed(1),D=i.bones.map(([Y,$])=>{let ce=r[Y],P=r[$];if(!ce||!P)return"";let I=Math.max(Number.isFinite(n[Y])?n[Y]:-1,Number.isFinite(n[$])?n[$]:-1);return`<line x1="${F(ce)}" y1="${B(ce)}" x2="${F(P)}" y2="${B(P)}" stroke="${jc(I<0?null:I)}" stroke-width="3" stroke-linecap="round"/>`}).join(""),V=`<line x1="4" y1="${(f-y/2).toFixed(1)}" x2="${(O-4).toFixed(1)}" y2="${(f-y/2).toFixed(1)}" class="floor"/>`;return`<figure class="view"><svg viewBox="0 0 ${O.toFixed(0)} ${f}" width="${O.toFixed(0)}" height="${f}" role="img" aria-label="${Le(H)}">${V}${D}</svg><figcaption>${Le(H)}</figcaption></figure>`};return`<div class="still">${R("front",m,g,"front")}${R("side",v,p,"right side")}</div>`}function m1(i){let e=i.action_level_secs.reduce((r,o)=>r+o,0),t=e+i.unscored_secs,n=i.action_level_secs.map((r,o)=>{let a=e>0?r/e*100:0;return`<tr class="al-row al${o+1}"><th>${o+1}</th><td>${Le(c1[o+1])}</td><td class="num">${Va(r)}</td><td class="num">${To(a,1)} %</td><td><div class="sharebar"><div class="bar"><span class="seg lvl${o+1}" style="width:${a.toFixed(2)}%"></span></div></div></td></tr>`}).join(""),s=t>0?`<tr class="muted"><th>–</th><td>not scored (operator not seen well enough)</td><td class="num">${Va(i.unscored_secs)}</td><td class="num">${To(i.unscored_secs/t*100,1)} % of all</td><td></td></tr>`:"";return`<table class="regions f-levels"><thead><tr><th>Level</th><th>RULA's meaning</th><th class="num">time</th><th class="num">share of scored time</th><th></th></tr></thead><tbody>${n}${s}</tbody></table>`}function g1(i,e){return e.worst_moments.length?`<div class="moments">${e.worst_moments.map((t,n)=>{let s=i.n?Uo(i.t,t.t):-1,r=t.regions.length?t.regions.map(a=>`${Le(Yd(`${a.side?`${a.side} `:""}${a.region}`))} ${a.score}`).join(" · "):"no region at its warning score",o=a=>a??"–";return`<div class="moment"><div class="m-head"><b>${n+1}. at ${To(t.t,1)} s</b> <span class="badge al${t.action_level}">action level ${t.action_level}</span></div><div class="small">grand score L ${o(t.grand_left)} · R ${o(t.grand_right)}</div>${s>=0?p1(i,s):""}<div class="small">${r}</div></div>`}).join("")}</div>`:'<p class="muted">No moment reached action level 2: nothing to show here.</p>'}function _1(i){return`<table class="regions f-regions"><thead><tr><th>Region</th><th>Verdict</th><th>What was found</th><th>Recommendation</th></tr></thead><tbody>${i.regions.map(t=>{let[n,s,r]=h1(t.verdict,i.dwell_s),o=Yd(`${t.side?`${t.side} `:""}${t.region}`),a;t.verdict==="not_scored"?a='<span class="muted">not scored</span>':(a=`highest ${t.highest} of ${t.top}`,t.share_at_warn>0?a+=`; at ${t.warn_at} or more for ${To(t.share_at_warn*100,1)} % of the time (${Va(t.secs_at_warn)}, ${t.episodes_at_warn} stretch${t.episodes_at_warn===1?"":"es"}, longest ${Va(t.longest_at_warn_secs)})`:a+=`; never at ${t.warn_at} or more`,t.warnings_raised&&(a+=`; ${t.warnings_raised} warning${t.warnings_raised===1?"":"s"} raised`));let c=t.advice_text?Le(Yd(t.advice_text)):'<span class="muted">–</span>';return`<tr data-region="${Le(t.region)}" data-side="${Le(t.side)}"><th>${Le(o)}</th><td><span class="badge ${s}" title="${Le(r)}">${Le(n)}</span></td><td class="small">${a}</td><td>${c}</td></tr>`}).join("")}</tbody></table>`}function x0(i,e){let t=e[0],n=t.findings;if(i.classList.toggle("none",!n),!n){i.innerHTML='<h1>Findings</h1><p class="muted">This review data holds no findings (written by an older ergocell).</p>';return}let s=new Map;for(let m of n.regions)m.warn_at!=null&&!s.has(m.region)&&s.set(m.region,m.warn_at);let r=new Map;for(let m of s.values())r.set(m,(r.get(m)||0)+1);let o=[...r].sort((m,g)=>g[1]-m[1])[0]?.[0],a=[o,...[...s].filter(([,m])=>m!==o).map(([m,g])=>`${m} ${g}`)].filter(m=>m!=null).join("; "),c=`${To(n.dwell_s,0)} s`,l=t.facts,d=t.n>1?Va(t.t[t.n-1]-t.t[0]):"–",u=[l.height_m!=null?`operator ${l.height_m.toFixed(2)} m`:null,l.height_class?`height class ${Le(l.height_class)}`:null,l.approved_by.length?`robot trajectory approved by ${l.approved_by.map(Le).join(", ")}`:null].filter(Boolean).join(" · "),h=e.length>1?' <span class="muted">(session A of the comparison)</span>':"";i.innerHTML=`<h1>Ergonomic findings${h}</h1>
<p class="f-sub"><b>${Le(t.label)}</b> · ${d} recorded${u?` · ${u}`:""}</p>
<h2>Time at each RULA action level <span class="hint">the worse side, every frame (McAtamney &amp; Corlett 1993)</span></h2>
${m1(n)}
<h2>The worst moments <span class="hint">highest action level first, one per stretch, at least 10 s apart; the skeleton as fused, from the front and the operator's right, coloured by each region's RULA score (1 deep blue … 7 deep red)</span></h2>
${g1(t,n)}
<h2>Per body region <span class="hint">"warning score": the region score at which ergocell's shipped settings warn the operator (${Le(a)}). Change: held there ${c} or more, or warned. Brief: only for moments under ${c}. The recommendation is the advice the warnings give for the region's worst posture.</span></h2>
${_1(n)}`}var x1=[.25,.5,1,2,4],y0='<svg viewBox="0 0 16 16" width="14" height="14" aria-hidden="true"><path d="M4 2v12l10-6z" fill="currentColor"/></svg>',v1='<svg viewBox="0 0 16 16" width="14" height="14" aria-hidden="true"><path d="M3 2h4v12H3zM9 2h4v12H9z" fill="currentColor"/></svg>';function y1(){if(!document.querySelector('link[rel~="icon"]')){let i=document.createElement("link");i.rel="icon",i.href="data:,",document.head.appendChild(i)}}function b1(){let i=document.getElementById("app");return i||(i=document.createElement("div"),i.id="app",document.body.appendChild(i)),i}function bh(i,e,t){i.innerHTML=`<header class="topbar"><div class="brand">ergocell <span>review</span></div></header><div class="message-card"><h1>${Le(e)}</h1><p>${Le(t)}</p></div>`}function S1(){let i=[];for(let e=1;e<=uo;e++){let[t,n,s]=ho((e-1)/(uo-1)),r=.299*t+.587*n+.114*s>140;i.push(`<span style="background:${Qc(e)};color:${r?"#111":"#fff"}">${e}</span>`)}return`<div class="score-ramp" aria-label="score 1 deep blue to score 7 deep red">${i.join("")}</div>`}function M1(i){let e=i.length>1,t=i.flatMap((r,o)=>r.source.problems.map(a=>e?`${"AB"[o]} · ${r.label}: ${a}`:a)),n=e?`<div class="seg-select" id="session-select" role="tablist" aria-label="Session shown in 3D">${i.map((r,o)=>`<button role="tab" data-i="${o}"><span class="sess-dot" style="background:${is[o]}"></span>${"AB"[o]} · ${Le(r.label)}</button>`).join("")}</div>`:"",s=e?`${Le(i[0].label)} <span class="vs">vs</span> ${Le(i[1].label)}`:Le(i[0].label);return`
<header class="topbar">
  <div class="brand">ergocell <span>review</span></div>
  <div class="title" title="${Le(i.map(r=>r.label).join(" vs "))}">${s}</div>
  ${n}
  <button class="tool" id="findings-toggle" aria-pressed="false" title="The findings: the printed report's first page">Findings</button>
  <button class="tool" id="print" title="Print, or save as PDF: the findings first, then the session facts, warnings, robot and state changes, the timeline, body regions and task segments, and the joint angles">Print report</button>
</header>
<section class="card findings" id="findings"></section>
${i.filter(r=>r.overview).map(r=>{let o=r.overview,a=o.windows.reduce((c,[l,d])=>c+(d-l),0);return`<div class="banner note" id="overview-note"><b>${e?`${Le(r.label)}: `:""}Overview of a long recording.</b> This page holds ${o.kept.toLocaleString("en")} of its ${o.recorded.toLocaleString("en")} frames: every frame of the worst moments (${o.windows.length} stretch${o.windows.length===1?"":"es"}, ${Math.round(a/60)} min: action level 3 or more, and warnings, with 30 s either side), elsewhere the worst frame of each ${o.bucketS.toFixed(1)} s. The body-region rows, shares, exposure and angle distributions are over every frame.</div>`}).join("")}
${t.length?`<div class="banner" role="alert"><b>${t.length===1?"Problem with the recording":`${t.length} problems with the recordings`}</b> — only what could be read is shown.<ul>${t.map(r=>`<li>${Le(r)}</li>`).join("")}</ul></div>`:""}
<main class="layout${e?" compare":""}">
  <section class="card viewer">
    <div class="viewport" id="viewport">
      <div class="overlay top-left"><span class="session-badge" id="session-badge"></span></div>
      <div class="overlay legend" aria-label="Strain colour legend">
        <div class="legend-title">RULA score of each joint's region</div>
        ${S1()}
        <div class="ramp-note">One colour per score, the same in every region. A region's scale ends at its own top: legs 2, forearm 3, wrist 4, upper arm, neck and trunk 6 (7: the grand score only).</div>
        <div class="legend-keys"><span><i class="dot grey"></i>not scored</span><span><i class="dot tcp"></i>robot TCP</span><span><i class="dot handover"></i>handover point</span></div>
      </div>
      <div class="overlay bottom-left readout" id="readout"></div>
      <div class="overlay bottom-right hint">drag to orbit · right-drag to pan · wheel to zoom</div>
      <div class="view-message" id="view-empty" hidden><span class="msg">No frames were recorded in this session.</span></div>
    </div>
    <div class="transport">
      <button id="step-back" title="Step back (←)" aria-label="Step back"><svg viewBox="0 0 16 16" width="14" height="14" aria-hidden="true"><path d="M3 2h2v12H3zM14 2v12L6 8z" fill="currentColor"/></svg></button>
      <button id="play" class="primary" title="Play / pause (space)" aria-label="Play">${y0}</button>
      <button id="step-forward" title="Step forward (→)" aria-label="Step forward"><svg viewBox="0 0 16 16" width="14" height="14" aria-hidden="true"><path d="M11 2h2v12h-2zM2 2v12l8-6z" fill="currentColor"/></svg></button>
      <input type="range" id="scrubber" min="0" max="0" step="1" value="0" aria-label="Time">
      <label class="speed">speed <select id="speed">${x1.map(r=>`<option value="${r}"${r===1?" selected":""}>${r}×</option>`).join("")}</select></label>
      <span id="frame-counter" class="counter">frame 0 / 0 · 0.00 s</span>
    </div>
  </section>
  <aside class="side">
    <section class="card" id="facts"></section>
    <section class="card" id="warnings"></section>
    <section class="card" id="robot"></section>
    <section class="card" id="states"></section>
  </aside>
  <section class="card timeline-card">
    <h2>Timeline <span class="hint">RULA grand score per side and action level · dashed flags are warnings (hover)${i.some(r=>r.hasUncertain)?" · hatched band at the bottom: a side's score is uncertain":""}${i.some(r=>r.robotLegs.length||r.robotHolds.length||r.robotEvents.length||r.partsTaken.length)?" · strip at the top: robot legs (dashed end: planned, not reported), red ticks: holds, diamonds: controller events and parts taken":""} · click to jump</span></h2>
    <div id="timeline"></div>
  </section>
  <section class="card" id="regions"></section>
  <section class="card" id="segments"></section>
  <section class="card" id="angles"></section>
</main>
<footer class="foot">ergocell review · RULA scores per frame from the fused 3D skeleton · lengths in metres, angles in degrees</footer>`}var v0=["not scored","acceptable","investigate further","investigate, change soon","investigate, change now"],w1=["upper arm","lower arm","wrist","neck","trunk"];function E1(i,e){let t=(e||[]).map((o,a)=>[w1[a],o]).filter(([o,a])=>o&&a!=null);if(!t.length)return"";let[n,s]=t.reduce((o,a)=>a[1]<o[1]?a:o),r=`${i} side, probability that each region's band is right: ${t.map(([o,a])=>`${o} ${Math.round(a*100)} %`).join(", ")}`;return`<span class="sure${s<.9?" near":""}" title="${Le(r)}">${Le(n)} ${Math.round(s*100)} % sure</span>`}function T1(i,e){let t=u=>u??"–",n=i.actionLevel[e],s=i.t[e],r=null;for(let u of i.facts.states)Number(u.t)<=s+1e-9&&(r=u.state);let o=n==null?"":`<span class="al al${n}">action level ${n}${v0[n]?` · ${v0[n]}`:""}</span>`,a=(u,h,m,g,v,p)=>{let f=v&&g!=null,y=f?` title="${u} score ${g} rests on low-confidence landmarks or held inputs (uncertain)"`:"";return`<span class="gs${f?" unc":""}"${y}><i style="background:${m}"></i>${h} ${t(g)}${f?'<span class="q">?</span>':""}</span>${g==null?"":E1(u,p)}`},c=Xa(i.robotLegs,s),l=c?`<span class="rl"><i style="background:${wo(c)}"></i>robot ${Le(c.leg||"leg")}</span>`:"",d=i.hasReba?`<span class="st" title="REBA score (Hignett &amp; McAtamney 2000) per side, 1–15">REBA L ${t(i.rebaLeft[e])} · R ${t(i.rebaRight[e])}</span>`:"";return`${a("Left","L",Mo.left,i.grandLeft[e],i.uncertainLeft[e],i.bandLeft[e])}${a("Right","R",Mo.right,i.grandRight[e],i.uncertainRight[e],i.bandRight[e])}${o}${d}${r?`<span class="st">${Le(String(r).replace(/_/g," "))}</span>`:""}${l}`}function A1(i,e){let t=e&&Array.isArray(e.sessions)?e.sessions:null;if(!t){bh(i,"The review data is not in the expected format",'Expected an object with a "sessions" list.');return}if(!t.length){bh(i,"Nothing to review","The recording contains no session: no frames, facts or warnings could be read from it.");return}let n=t.slice(0,2).map(xf);i.innerHTML=M1(n),document.title=document.title&&document.title!=="…"?document.title:`ergocell review · ${n.map(T=>T.label).join(" vs ")}`;let s=T=>document.getElementById(T),r=s("play"),o=s("scrubber"),a=s("frame-counter"),c=s("speed"),l=new eh(s("viewport")),d=s("readout"),u={si:0,frame:0,playing:!1,time:0,last:0,raf:0},h=()=>n[u.si];function m(T){return()=>T===u.si&&n[T].n?n[T].t[u.frame]:null}let g=s("timeline"),v=n.map((T,F)=>{let B=document.createElement("div");if(B.className="tl",n.length>1){let V=document.createElement("div");V.className="tl-head",V.innerHTML=`<span class="sess-dot" style="background:${is[F]}"></span>${"AB"[F]} · ${Le(T.label)}`,B.appendChild(V)}let D=document.createElement("div");return D.className="tl-plot",B.appendChild(D),g.appendChild(B),{wrap:B,plot:D,s:T,si:F}});v.forEach(T=>{T.chart=Kg(T.plot,T.s,{height:n.length>1?150:190,cursorTime:m(T.si),onSeek:F=>M(T.si,F)})});let p=(T,F)=>M(T,F);x0(s("findings"),n),s("findings-toggle").addEventListener("click",()=>{let T=document.body.classList.toggle("show-findings");s("findings-toggle").setAttribute("aria-pressed",String(T))}),s("print").addEventListener("click",()=>window.print()),r0(s("facts"),n),l0(s("warnings"),n,p),a0(s("robot"),n,p),o0(s("states"),n,p),u0(s("regions"),n),d0(s("segments"),n),f0(s("angles"),n);function f(){let T=h(),F=T.n,B=F?u.frame:0;l.setFrame(B),o.max=String(Math.max(0,F-1)),o.value=String(B);let D=F?T.t[B]:0;a.textContent=`frame ${F?B+1:0} / ${F} · ${D.toFixed(2)} s`,d.innerHTML=F?T1(T,B):"";let V=u.playing?"Pause":"Play";r.getAttribute("aria-label")!==V&&(r.innerHTML=u.playing?v1:y0,r.setAttribute("aria-label",V)),r.classList.toggle("active",u.playing);for(let Y of v)Y.chart.redraw()}function y(T,F=!0){let B=h().n?h().t[u.frame]:0;u.si=T;let D=h();l.setSession(D),u.frame=F&&D.n?Uo(D.t,B):0;let V=D.n===0;for(let Y of["play","step-back","step-forward","scrubber"])s(Y).disabled=V;s("view-empty").hidden=!V,s("session-badge").innerHTML=n.length>1?`<span class="sess-dot" style="background:${is[T]}"></span>${"AB"[T]} · ${Le(D.label)}`:Le(D.label),document.querySelectorAll("#session-select button").forEach(Y=>Y.classList.toggle("active",Number(Y.dataset.i)===T)),v.forEach(Y=>Y.wrap.classList.toggle("active",Y.si===T)),f()}function C(T){let F=h().n;u.frame=F?Math.min(F-1,Math.max(0,T)):0,f()}function M(T,F){_(),T!==u.si&&y(T,!1);let B=h();B.n&&C(Uo(B.t,F))}function R(T){if(!u.playing)return;let F=h(),B=Math.min(.25,Math.max(0,(T-u.last)/1e3));u.last=T,u.time+=B*Number(c.value||1);let D=F.t[F.n-1];if(u.time>=D){u.frame=F.n-1,u.playing=!1,f();return}let V=Cr(F.t,u.time);V!==u.frame&&(u.frame=V,f()),u.raf=requestAnimationFrame(R)}function b(){let T=h();!T.n||u.playing||(u.frame>=T.n-1&&(u.frame=0),u.playing=!0,u.time=T.t[u.frame],u.last=performance.now(),f(),u.raf=requestAnimationFrame(R))}function _(){u.playing&&(u.playing=!1,cancelAnimationFrame(u.raf),f())}let A=()=>u.playing?_():b(),H=T=>{_(),C(u.frame+T)};r.addEventListener("click",A),s("step-back").addEventListener("click",()=>H(-1)),s("step-forward").addEventListener("click",()=>H(1)),o.addEventListener("input",()=>{_(),C(Number(o.value))}),c.addEventListener("change",()=>{u.playing&&(u.time=h().t[u.frame])}),document.querySelectorAll("#session-select button").forEach(T=>T.addEventListener("click",()=>{_(),y(Number(T.dataset.i))}));let O=T=>T&&(T.tagName==="SELECT"||T.tagName==="TEXTAREA"||T.tagName==="INPUT"&&T.type!=="range");window.addEventListener("keydown",T=>{T.ctrlKey||T.metaKey||T.altKey||O(T.target)||(T.code==="Space"||T.key===" "?(T.preventDefault(),T.repeat||A()):(T.key==="ArrowLeft"||T.key==="ArrowRight")&&(T.preventDefault(),H(T.key==="ArrowLeft"?-1:1)))}),window.addEventListener("keyup",T=>{(T.code==="Space"||T.key===" ")&&!O(T.target)&&T.preventDefault()}),window.ergocellReview={frame:()=>u.frame,frameCount:()=>h().n,playing:()=>u.playing,session:()=>u.si,time:()=>h().n?h().t[u.frame]:0,timeOf:T=>h().n?h().t[Math.min(h().n-1,Math.max(0,T))]:0,seek:(T,F=u.si)=>M(F,T)},y(0,!1)}async function R1(){y1();let i=b1();i.innerHTML='<div class="message-card"><p>Loading the recording…</p></div>';let e;try{e=await _f()}catch(t){bh(i,"Could not load the review data",t.message||String(t));return}try{A1(i,e)}catch(t){throw bh(i,"The review page could not show this recording",t.message||String(t)),t}}R1();})();
